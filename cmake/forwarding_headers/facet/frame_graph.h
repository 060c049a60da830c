// Kept for one release, for apps that include this old path: include "facet/runtime/frame_graph.h" instead.
#include "facet/runtime/frame_graph.h"
