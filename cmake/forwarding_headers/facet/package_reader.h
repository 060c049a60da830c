// Kept for one release, for apps that include this old path: include "facet/package/package_reader.h" instead.
#include "facet/package/package_reader.h"
