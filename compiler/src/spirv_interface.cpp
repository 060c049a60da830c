#include "facet/compiler/spirv_interface.h"

#include "spirv_cross_session.h"

namespace facet::compiler {
namespace {

// vec4 slots of one interface variable: a location per vector (or matrix column), times the
// array length. GLSL ES packs small varyings more tightly (ES 3.00 §A, "Counting of Inputs and
// Outputs"); one slot per location is the count drivers are guaranteed to accept.
uint32_t slots(spvc_compiler compiler, spvc_type_id typeId) {
  spvc_type type = spvc_compiler_get_type_handle(compiler, typeId);
  uint32_t n = spvc_type_get_columns(type);
  for (unsigned d = 0; d < spvc_type_get_num_array_dimensions(type); ++d) n *= spvc_type_get_array_dimension(type, d);
  return n;
}

}  // namespace

bool analyseStageInterface(const std::vector<uint32_t>& words, StageInterface* out, std::string* error) {
  *out = {};
  SpirvCrossSession session;
  if (!session.open(words, SPVC_BACKEND_NONE, error)) return false;
  spvc_compiler compiler = session.compiler();
  // Only what the stage's code reaches counts, as a GLES driver counts active uniforms.
  spvc_set active = nullptr;
  spvc_resources resources = nullptr;
  if (spvc_compiler_get_active_interface_variables(compiler, &active) != SPVC_SUCCESS ||
      spvc_compiler_create_shader_resources_for_active_variables(compiler, &resources, active) != SPVC_SUCCESS)
    return session.fail("reflection", error);

  auto each = [&](spvc_resource_type kind, auto&& visit) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    if (spvc_resources_get_resource_list_for_type(resources, kind, &list, &count) != SPVC_SUCCESS) return false;
    for (size_t i = 0; i < count; ++i) visit(list[i]);
    return true;
  };
  bool ok = each(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,
                 [&](const spvc_reflected_resource& r) { out->samplers += slots(compiler, r.type_id); }) &&
            each(SPVC_RESOURCE_TYPE_STAGE_INPUT,
                 [&](const spvc_reflected_resource& r) {
                   out->inputVectors += slots(compiler, r.type_id);
                   if (spvc_compiler_has_decoration(compiler, r.id, SpvDecorationRelaxedPrecision))
                     out->relaxedInputs.push_back(r.name);
                 }) &&
            each(SPVC_RESOURCE_TYPE_STAGE_OUTPUT,
                 [&](const spvc_reflected_resource& r) { out->outputVectors += slots(compiler, r.type_id); }) &&
            each(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, [&](const spvc_reflected_resource& r) {
              size_t bytes = 0;
              spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, r.base_type_id),
                                                     &bytes);
              out->uniformVectors += uint32_t((bytes + 15) / 16);
            });
  if (!ok) return session.fail("resource list", error);
  return true;
}

}  // namespace facet::compiler
