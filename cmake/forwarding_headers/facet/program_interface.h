// Kept for one release, for apps that include this old path: include "facet/package/program_interface.h" instead.
#include "facet/package/program_interface.h"
