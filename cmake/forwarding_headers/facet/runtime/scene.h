// Kept for one release, for apps that include this old path: include "facet/scene/scene.h" instead.
#include "facet/scene/scene.h"
