// Kept for one release, for apps that include this old path: include "facet/scene/post_settings.h" instead.
#include "facet/scene/post_settings.h"
