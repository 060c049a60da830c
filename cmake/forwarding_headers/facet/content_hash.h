// Kept for one release, for apps that include this old path: include "facet/runtime/content_hash.h" instead.
#include "facet/runtime/content_hash.h"
