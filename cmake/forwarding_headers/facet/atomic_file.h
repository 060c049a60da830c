// Kept for one release, for apps that include this old path: include "facet/package/atomic_file.h" instead.
#include "facet/package/atomic_file.h"
