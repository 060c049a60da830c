#include "facet/compiler/msl_backend.h"

#include "facet/shader_abi.h"
#include "spirv_cross_session.h"

namespace facet::compiler {

std::vector<package::MslBinding> materialMslBindings(const package::MaterialInfo& material) {
  std::vector<package::MslBinding> out;
  auto block = [&](const abi::BlockDesc& b) {
    out.push_back({std::string(b.name), package::MslResource::Buffer, b.set, b.binding, abi::mslBufferIndex(b)});
  };
  auto sampler = [&](std::string name, uint32_t set, uint32_t binding) {
    out.push_back({std::move(name), package::MslResource::Texture, set, binding, abi::mslTextureIndex(binding)});
  };
  block(abi::kFrameBlock);
  block(abi::kObjectBlock);
  if (material.paramBlockSize != 0) block(abi::kMaterialBlock);
  if (material.shading == "lit")
    for (const abi::SamplerDesc& s : abi::kFrameSamplers) sampler(std::string(s.name), s.set, s.binding);
  for (const package::Param& p : material.params)
    if (package::isTexture(p.type) && p.offset != package::kNoTextureSlot)
      sampler(abi::kMaterialSamplerPrefix + p.name, abi::kTextureSet, abi::materialTextureBinding(p.offset));
  return out;
}

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
  if (spvc_compiler_install_compiler_options(compiler, options) != SPVC_SUCCESS) return session.fail("install options", error);
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
