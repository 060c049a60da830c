// Kept for one release, for apps that include this old path: include "facet/runtime/render_path.h" instead.
#include "facet/runtime/render_path.h"
