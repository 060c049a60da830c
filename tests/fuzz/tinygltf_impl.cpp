// tinygltf's implementation compiled into fuzz_gltf with the fuzzer's instrumentation (the
// runtime links Debian's shared library, which libFuzzer and ASan cannot see into). The same
// header and version as that library; images are never decoded by the loader (its own callback),
// so stb_image is left out (TINYGLTF_NO_STB_IMAGE, set for the whole target in CMakeLists.txt).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
