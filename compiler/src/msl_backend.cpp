#include "facet/compiler/msl_backend.h"

#include "spirv_cross_session.h"

namespace facet::compiler {

bool spirvToMsl(const std::vector<uint32_t>& words, std::span<const package::MslBinding> slots, std::string* msl,
                std::string* error) {
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
  if (spvc_compiler_install_compiler_options(compiler, options) != SPVC_SUCCESS)
    return session.fail("install options", error);
  // Fixed slots, so a Metal app binds every variant the same way (SPIRV-Cross would otherwise
  // number each shader's resources in order of use: facet_environment was texture(0) in one
  // variant and texture(2) in another).
  const SpvExecutionModel stage = spvc_compiler_get_execution_model(compiler);
  for (const package::MslBinding& slot : slots) {
    spvc_msl_resource_binding binding;
    spvc_msl_resource_binding_init(&binding);
    binding.stage = stage;
    binding.desc_set = slot.set;
    binding.binding = slot.binding;
    if (slot.kind == package::MslResource::Buffer) {
      binding.msl_buffer = slot.index;
    } else {
      binding.msl_texture = slot.index;
      binding.msl_sampler = slot.index;
    }
    if (spvc_compiler_msl_add_resource_binding(compiler, &binding) != SPVC_SUCCESS)
      return session.fail("MSL resource binding", error);
  }
  const char* source = nullptr;
  if (spvc_compiler_compile(compiler, &source) != SPVC_SUCCESS) return session.fail("compile", error);
  *msl = source;
  return true;
}

}  // namespace facet::compiler
