// Kept for one release, for apps that include this old path: include "facet/runtime/render_backend.h" instead.
#include "facet/runtime/render_backend.h"
