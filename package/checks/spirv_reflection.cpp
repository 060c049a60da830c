#include "spirv_reflection.h"

#include <spirv_cross_c.h>

#include <algorithm>
#include <memory>

namespace facet::package {
namespace {

const char* executionModelName(SpvExecutionModel model) {
  switch (model) {
    case SpvExecutionModelVertex: return "vertex";
    case SpvExecutionModelTessellationControl: return "tessellation control";
    case SpvExecutionModelTessellationEvaluation: return "tessellation evaluation";
    case SpvExecutionModelGeometry: return "geometry";
    case SpvExecutionModelFragment: return "fragment";
    case SpvExecutionModelGLCompute: return "compute";
    case SpvExecutionModelKernel: return "kernel";
    default: return "non-graphics";
  }
}

struct ContextDeleter {
  void operator()(spvc_context_s* context) const { spvc_context_destroy(context); }
};

class Reflector {
 public:
  explicit Reflector(spvc_compiler compiler) : compiler_(compiler) {}

  ValueType valueType(spvc_type_id id) const {
    spvc_type type = spvc_compiler_get_type_handle(compiler_, id);
    ValueType out;
    switch (spvc_type_get_basetype(type)) {
      case SPVC_BASETYPE_FP32: out.kind = ScalarKind::Float; break;
      case SPVC_BASETYPE_INT32: out.kind = ScalarKind::Int; break;
      case SPVC_BASETYPE_UINT32: out.kind = ScalarKind::Uint; break;
      case SPVC_BASETYPE_BOOLEAN: out.kind = ScalarKind::Bool; break;
      default: out.kind = ScalarKind::Other; break;
    }
    out.components = spvc_type_get_vector_size(type);
    out.columns = spvc_type_get_columns(type);
    out.arraySize = arraySize(type);
    return out;
  }

  // Elements of an array type (the product of its dimensions), 0 for one value; a length given by
  // a specialization constant counts as unknown, which no check accepts.
  uint32_t arraySize(spvc_type type) const {
    const unsigned dimensions = spvc_type_get_num_array_dimensions(type);
    if (dimensions == 0) return 0;
    uint64_t n = 1;
    for (unsigned d = 0; d < dimensions; ++d) {
      if (!spvc_type_array_dimension_is_literal(type, d)) return ~0u;
      n *= spvc_type_get_array_dimension(type, d);
      if (n > ~0u) return ~0u;
    }
    return uint32_t(n);
  }

  uint32_t decoration(spvc_variable_id id, SpvDecoration d) const {
    return spvc_compiler_get_decoration(compiler_, id, d);
  }

  bool builtIn(const spvc_reflected_resource& r) const {
    if (spvc_compiler_has_decoration(compiler_, r.id, SpvDecorationBuiltIn)) return true;
    spvc_type type = spvc_compiler_get_type_handle(compiler_, r.base_type_id);
    return spvc_type_get_basetype(type) == SPVC_BASETYPE_STRUCT && spvc_type_get_num_member_types(type) > 0 &&
           spvc_compiler_has_member_decoration(compiler_, r.base_type_id, 0, SpvDecorationBuiltIn);
  }

  ReflectedBlock block(const spvc_reflected_resource& r) const {
    ReflectedBlock b;
    spvc_type type = spvc_compiler_get_type_handle(compiler_, r.base_type_id);
    b.name = spvc_compiler_get_name(compiler_, r.base_type_id);
    b.set = decoration(r.id, SpvDecorationDescriptorSet);
    b.binding = decoration(r.id, SpvDecorationBinding);
    b.arraySize = arraySize(spvc_compiler_get_type_handle(compiler_, r.type_id));
    size_t size = 0;
    spvc_compiler_get_declared_struct_size(compiler_, type, &size);
    b.bytes = uint32_t(std::min<size_t>(size, ~0u));
    for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i) {
      ReflectedMember m;
      m.name = spvc_compiler_get_member_name(compiler_, r.base_type_id, i);
      unsigned offset = 0;
      size_t memberSize = 0;
      spvc_compiler_type_struct_member_offset(compiler_, type, i, &offset);
      spvc_compiler_get_declared_struct_member_size(compiler_, type, i, &memberSize);
      m.offset = offset;
      m.size = uint32_t(std::min<size_t>(memberSize, ~0u));
      m.type = valueType(spvc_type_get_member_type(type, i));
      b.members.push_back(std::move(m));
    }
    return b;
  }

  ReflectedSampler sampler(const spvc_reflected_resource& r) const {
    ReflectedSampler s;
    s.name = r.name;
    s.set = decoration(r.id, SpvDecorationDescriptorSet);
    s.binding = decoration(r.id, SpvDecorationBinding);
    spvc_type type = spvc_compiler_get_type_handle(compiler_, r.type_id);
    s.arraySize = arraySize(type);
    spvc_type image = spvc_compiler_get_type_handle(compiler_, r.base_type_id);
    const SpvDim dim = spvc_type_get_image_dimension(image);
    const bool depth = spvc_type_get_image_is_depth(image);
    const bool plain = !spvc_type_get_image_arrayed(image) && !spvc_type_get_image_multisampled(image) &&
                       spvc_type_get_basetype(spvc_compiler_get_type_handle(
                           compiler_, spvc_type_get_image_sampled_type(image))) == SPVC_BASETYPE_FP32;
    s.shape = !plain              ? SamplerShape::Other
              : depth             ? (dim == SpvDim2D ? SamplerShape::Shadow2D : SamplerShape::Other)
              : dim == SpvDim2D   ? SamplerShape::Flat2D
              : dim == SpvDimCube ? SamplerShape::Cube
                                  : SamplerShape::Other;
    return s;
  }

  ReflectedVariable variable(const spvc_reflected_resource& r) const {
    ReflectedVariable v;
    v.name = r.name;
    if (spvc_compiler_has_decoration(compiler_, r.id, SpvDecorationLocation))
      v.location = decoration(r.id, SpvDecorationLocation);
    v.type = valueType(r.type_id);
    return v;
  }

 private:
  spvc_compiler compiler_;
};

}  // namespace

bool reflectSpirv(const std::vector<uint32_t>& words, package::Stage stage, ReflectedStage* out, std::string* error) {
  spvc_context raw = nullptr;
  if (spvc_context_create(&raw) != SPVC_SUCCESS) {
    *error = "cannot be reflected (SPIRV-Cross: no context)";
    return false;
  }
  std::unique_ptr<spvc_context_s, ContextDeleter> context(raw);
  const auto fail = [&](const char* step) {
    *error =
        std::string("cannot be reflected (SPIRV-Cross ") + step + ": " + spvc_context_get_last_error_string(raw) + ")";
    return false;
  };
  spvc_parsed_ir ir = nullptr;
  spvc_compiler compiler = nullptr;
  if (spvc_context_parse_spirv(raw, words.data(), words.size(), &ir) != SPVC_SUCCESS) return fail("parse");
  if (spvc_context_create_compiler(raw, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) !=
      SPVC_SUCCESS)
    return fail("compiler");

  const spvc_entry_point* entries = nullptr;
  size_t entryCount = 0;
  if (spvc_compiler_get_entry_points(compiler, &entries, &entryCount) != SPVC_SUCCESS) return fail("entry points");
  const SpvExecutionModel expected =
      stage == package::Stage::Vertex ? SpvExecutionModelVertex : SpvExecutionModelFragment;
  if (entryCount != 1) {
    *error = "has " + std::to_string(entryCount) + " entry points; a package shader has exactly one, 'main'";
    return false;
  }
  if (entries[0].execution_model != expected) {
    *error = std::string("is a ") + executionModelName(entries[0].execution_model) + " shader (its entry point '" +
             entries[0].name + "' has that execution model), not a " + package::toString(stage) + " shader";
    return false;
  }
  if (std::string(entries[0].name) != "main") {
    *error = std::string("names its entry point '") + entries[0].name + "'; the runtime calls 'main'";
    return false;
  }

  // Uniforms and samplers as the entry point uses them (a driver ignores the others); stage
  // inputs and outputs as declared (Vulkan matches declared interfaces).
  spvc_set active = nullptr;
  spvc_resources used = nullptr, declared = nullptr;
  if (spvc_compiler_get_active_interface_variables(compiler, &active) != SPVC_SUCCESS ||
      spvc_compiler_create_shader_resources_for_active_variables(compiler, &used, active) != SPVC_SUCCESS ||
      spvc_compiler_create_shader_resources(compiler, &declared) != SPVC_SUCCESS)
    return fail("reflection");
  const auto list = [](spvc_resources resources, spvc_resource_type kind) {
    const spvc_reflected_resource* items = nullptr;
    size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources, kind, &items, &count);
    return std::vector<spvc_reflected_resource>(items, items + count);
  };

  const Reflector reflector(compiler);
  *out = {};
  out->stage = stage;
  out->what = std::string(package::toString(stage)) + " shader (SPIR-V)";
  for (const spvc_reflected_resource& r : list(used, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER))
    out->blocks.push_back(reflector.block(r));
  for (const spvc_reflected_resource& r : list(used, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE))
    out->samplers.push_back(reflector.sampler(r));
  for (const spvc_reflected_resource& r : list(declared, SPVC_RESOURCE_TYPE_STAGE_INPUT))
    if (!reflector.builtIn(r)) out->inputs.push_back(reflector.variable(r));
  for (const spvc_reflected_resource& r : list(declared, SPVC_RESOURCE_TYPE_STAGE_OUTPUT))
    if (!reflector.builtIn(r)) out->outputs.push_back(reflector.variable(r));
  const std::pair<spvc_resource_type, const char*> unsupported[] = {
      {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, "storage buffer"},
      {SPVC_RESOURCE_TYPE_SUBPASS_INPUT, "subpass input"},
      {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, "storage image"},
      {SPVC_RESOURCE_TYPE_ATOMIC_COUNTER, "atomic counter"},
      {SPVC_RESOURCE_TYPE_PUSH_CONSTANT, "push constant block"},
      {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, "separate image"},
      {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, "separate sampler"},
      {SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE, "acceleration structure"},
  };
  for (const auto& [kind, what] : unsupported)
    for (const spvc_reflected_resource& r : list(used, kind))
      out->unsupported.push_back(std::string(what) + " '" + r.name + "'");
  return true;
}

}  // namespace facet::package
