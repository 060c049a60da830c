// Kept for one release, for apps that include this old path: include "facet/runtime/gl_backend.h" instead.
#include "facet/runtime/gl_backend.h"
