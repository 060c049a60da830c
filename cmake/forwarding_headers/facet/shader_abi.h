// Kept for one release, for apps that include this old path: include "facet/abi/shader_abi.h" instead.
#include "facet/abi/shader_abi.h"
