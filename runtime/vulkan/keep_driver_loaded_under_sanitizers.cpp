// Linked into every executable that creates a Vulkan backend (facet-view, matc, the tests), as
// the object library facet_keep_vulkan_driver_loaded; it does nothing outside ASan builds.
//
// LeakSanitizer and lavapipe (Mesa 22.3): every load of the driver allocates ~240 bytes that
// only the driver's globals point to. The loader unloads the driver at vkDestroyInstance; once
// its data segment is unmapped LeakSanitizer reports those bytes as leaked from
// "<unknown module>", which no suppression can match. Holding one extra reference keeps the
// driver mapped, so the bytes stay reachable; leaks in Facet's own code are reported as before.
// An app does not need it: the bytes are the driver's, allocated once per load.
// The same holds for the Khronos validation layer (C++; with synchronization validation on it
// keeps per-instance state that outlives vkDestroyInstance until the layer is unloaded).
#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>

namespace {
[[maybe_unused]] const bool kLavapipeKeptLoaded =
    dlopen("/usr/lib/x86_64-linux-gnu/libvulkan_lvp.so", RTLD_NOW | RTLD_LOCAL) != nullptr;
[[maybe_unused]] const bool kValidationLayerKeptLoaded =
    dlopen("/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_LOCAL) != nullptr;
}  // namespace
#endif
