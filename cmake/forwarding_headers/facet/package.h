// Kept for one release, for apps that include this old path: include "facet/package/package.h" instead.
#include "facet/package/package.h"
