#include "facet/compiler/msl_backend.h"

#include "spirv_cross_session.h"

namespace facet::compiler {

bool spirvToMsl(const std::vector<uint32_t>& words, std::string* msl, std::string* error) {
  SpirvCrossSession session;
  if (!session.open(words, SPVC_BACKEND_MSL, error)) return false;
  spvc_compiler compiler = session.compiler();
  spvc_compiler_options options = nullptr;
  if (spvc_compiler_create_compiler_options(compiler, &options) != SPVC_SUCCESS) return session.fail("options", error);
  spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_MSL_VERSION, SPVC_MAKE_MSL_VERSION(2, 0, 0));
  spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_MSL_PLATFORM, SPVC_MSL_PLATFORM_IOS);
  // Subpass inputs (the merged post pass) become [[color(n)]] framebuffer-fetch inputs, what
  // Apple's tile-based GPUs read without leaving tile memory. No effect on other shaders.
  spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_MSL_FRAMEBUFFER_FETCH_SUBPASS, SPVC_TRUE);
  if (spvc_compiler_install_compiler_options(compiler, options) != SPVC_SUCCESS) return session.fail("install options", error);
  const char* source = nullptr;
  if (spvc_compiler_compile(compiler, &source) != SPVC_SUCCESS) return session.fail("compile", error);
  *msl = source;
  return true;
}

}  // namespace facet::compiler
