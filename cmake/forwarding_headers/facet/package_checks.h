// Kept for one release, for apps that include this old path: include "facet/package/checks.h" instead.
#include "facet/package/checks.h"
