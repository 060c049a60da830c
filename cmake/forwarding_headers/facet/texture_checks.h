// Kept for one release, for apps that include this old path: include "facet/runtime/texture_checks.h" instead.
#include "facet/runtime/texture_checks.h"
