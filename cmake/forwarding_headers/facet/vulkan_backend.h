// Kept for one release, for apps that include this old path: include "facet/runtime/vulkan_backend.h" instead.
#include "facet/runtime/vulkan_backend.h"
