// The compiled shaders and the runtime agree on the binary interface: block layouts, bindings
// and vertex input locations are read back from SPIR-V with SPIRV-Cross and compared with
// shader_abi.h and with the parameter layout the package records.
#include <gtest/gtest.h>

#include <spirv_cross_c.h>
#include <algorithm>

#include <cstddef>
#include <cstring>
#include <map>
#include <regex>
#include <set>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/assemble.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

struct Member {
  uint32_t offset;
};
struct Block {
  uint32_t set = ~0u, binding = ~0u;
  size_t size = 0;
  std::map<std::string, uint32_t> offsets;
  std::vector<std::string> members;  // in declaration order
};
struct Reflection {
  std::map<std::string, Block> blocks;                            // by block type name
  std::map<std::string, uint32_t> inputs;                         // stage input name -> location
  std::map<std::string, std::pair<uint32_t, uint32_t>> samplers;  // name -> (set, binding)
};

Reflection reflect(const std::vector<uint8_t>& code) {
  Reflection r;
  std::vector<uint32_t> words(code.size() / 4);
  std::memcpy(words.data(), code.data(), words.size() * 4);
  spvc_context ctx = nullptr;
  spvc_context_create(&ctx);
  spvc_parsed_ir ir = nullptr;
  spvc_compiler compiler = nullptr;
  spvc_resources resources = nullptr;
  if (spvc_context_parse_spirv(ctx, words.data(), words.size(), &ir) != SPVC_SUCCESS ||
      spvc_context_create_compiler(ctx, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) !=
          SPVC_SUCCESS ||
      spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS) {
    ADD_FAILURE() << spvc_context_get_last_error_string(ctx);
    spvc_context_destroy(ctx);
    return r;
  }
  const spvc_reflected_resource* list = nullptr;
  size_t count = 0;
  spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, &list, &count);
  for (size_t i = 0; i < count; ++i) {
    spvc_type type = spvc_compiler_get_type_handle(compiler, list[i].base_type_id);
    Block b;
    b.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
    b.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
    spvc_compiler_get_declared_struct_size(compiler, type, &b.size);
    for (unsigned m = 0; m < spvc_type_get_num_member_types(type); ++m) {
      unsigned offset = 0;
      spvc_compiler_type_struct_member_offset(compiler, type, m, &offset);
      b.offsets[spvc_compiler_get_member_name(compiler, list[i].base_type_id, m)] = offset;
      b.members.push_back(spvc_compiler_get_member_name(compiler, list[i].base_type_id, m));
    }
    r.blocks[spvc_compiler_get_name(compiler, list[i].base_type_id)] = b;
  }
  spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_STAGE_INPUT, &list, &count);
  for (size_t i = 0; i < count; ++i)
    r.inputs[list[i].name] = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationLocation);
  spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, &list, &count);
  for (size_t i = 0; i < count; ++i)
    r.samplers[list[i].name] = {spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet),
                                spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding)};
  spvc_context_destroy(ctx);
  return r;
}

// The variant every check below looks at: the mobile tier with its directional light (an unlit
// material is built without the light: its variants are all dir0).
const facet::package::Variant& highDir1(const facet::compiler::BuildResult& built) {
  for (const auto& v : built.package.variants)
    if (v.key == "high.dir1" || (built.package.material.shading == "unlit" && v.key == "high.dir0")) return v;
  ADD_FAILURE() << "no variant high.dir1";
  return built.package.variants.at(0);
}

// Samplers of the material's own textures (kMaterialSamplerPrefix + param), leaving out the frame's.
size_t materialSamplers(const Reflection& r) {
  size_t n = 0;
  for (const auto& [name, where] : r.samplers) n += name.rfind(facet::abi::kMaterialSamplerPrefix, 0) == 0;
  return n;
}

const std::vector<uint8_t>& spirv(const facet::package::Variant& v, facet::package::Stage stage) {
  for (const auto& s : v.shaders)
    if (s.stage == stage && s.target == facet::package::Target::Spirv) return s.code;
  static const std::vector<uint8_t> none;
  return none;
}

}  // namespace

TEST(ShaderAbi, FrameAndObjectBlocksMatchTheRuntimeStructs) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  const auto& variant = highDir1(*built);
  Reflection vs = reflect(spirv(variant, facet::package::Stage::Vertex));
  Reflection fs = reflect(spirv(variant, facet::package::Stage::Fragment));

  using facet::abi::FrameUniforms;
  using facet::abi::ObjectUniforms;
  for (const Reflection* r : {&vs, &fs}) {
    ASSERT_TRUE(r->blocks.count("FrameUniforms"));
    const Block& frame = r->blocks.at("FrameUniforms");
    EXPECT_EQ(frame.set, 0u);
    EXPECT_EQ(frame.binding, facet::abi::kFrameBinding);
    EXPECT_EQ(frame.size, facet::abi::kFrameBlockSh3Size);  // SH3: band 4's entries are not declared
    EXPECT_EQ(frame.offsets.at("viewProjection"), offsetof(FrameUniforms, viewProjection));
    EXPECT_EQ(frame.offsets.at("cameraPosition"), offsetof(FrameUniforms, cameraPosition));
    EXPECT_EQ(frame.offsets.at("lightDirection"), offsetof(FrameUniforms, lightDirection));
    EXPECT_EQ(frame.offsets.at("lightColor"), offsetof(FrameUniforms, lightColor));
    EXPECT_EQ(frame.offsets.at("ambient"), offsetof(FrameUniforms, ambient));
    EXPECT_EQ(frame.offsets.at("punctualLights"), offsetof(FrameUniforms, punctualLights));
    EXPECT_EQ(frame.offsets.at("sh"), offsetof(FrameUniforms, sh));
  }
  const Block& object = vs.blocks.at("ObjectUniforms");
  EXPECT_EQ(object.binding, facet::abi::kObjectBinding);
  EXPECT_EQ(object.size, sizeof(ObjectUniforms));
  EXPECT_EQ(object.offsets.at("positionScale"), offsetof(ObjectUniforms, positionScale));
  EXPECT_EQ(object.offsets.at("positionOffset"), offsetof(ObjectUniforms, positionOffset));

  EXPECT_EQ(vs.inputs.at("a_position"), facet::abi::kAttribPosition);
  EXPECT_EQ(vs.inputs.at("a_normal"), facet::abi::kAttribNormal);
  // Every forward variant reads the instance stream (a draw of one object is one instance).
  EXPECT_EQ(vs.inputs.at("a_instanceRow0"), facet::abi::kAttribInstanceRow0);
  EXPECT_EQ(vs.inputs.at("a_instanceRow1"), facet::abi::kAttribInstanceRow1);
  EXPECT_EQ(vs.inputs.at("a_instanceRow2"), facet::abi::kAttribInstanceRow2);
}

// The compiler prints the blocks from shader_abi.h's tables: what SPIR-V declares is the table,
// member for member, at the table's set and binding and std140 size, in every variant of every
// example material (a block a stage does not use may be absent).
TEST(ShaderAbi, BlocksAndSamplersMatchTheTableMemberForMember) {
  for (const std::string& path : facet::test::exampleMaterials()) {
    auto built = facet::test::buildFile(path);
    ASSERT_TRUE(built);
    for (const auto& v : built->package.variants) {
      SCOPED_TRACE(path + " " + v.key);
      for (auto stage : {facet::package::Stage::Vertex, facet::package::Stage::Fragment}) {
        Reflection r = reflect(spirv(v, stage));
        for (const facet::abi::BlockDesc& desc : facet::abi::kBlocks) {
          auto it = r.blocks.find(std::string(desc.name));
          if (it == r.blocks.end()) continue;
          EXPECT_EQ(it->second.set, desc.set) << desc.name;
          EXPECT_EQ(it->second.binding, desc.binding) << desc.name;
          if (desc.members.empty()) continue;  // MaterialParams: the package's layout (next test)
          // The frame block of a preset's variant stops after SH3 (kFrameBlockSh3Size).
          EXPECT_EQ(it->second.size,
                    desc.name == facet::abi::kFrameBlock.name ? facet::abi::kFrameBlockSh3Size : desc.std140Size)
              << desc.name;
          std::vector<std::string> expected;
          for (const facet::abi::MemberDesc& m : desc.members) expected.emplace_back(m.name);
          EXPECT_EQ(it->second.members, expected) << desc.name;
        }
        EXPECT_TRUE(r.blocks.count("FrameUniforms") || stage == facet::package::Stage::Fragment);
        for (const auto& [name, where] : r.samplers) {
          bool known = name.rfind(facet::abi::kMaterialSamplerPrefix, 0) == 0;
          for (const facet::abi::SamplerDesc& desc : facet::abi::kFrameSamplers) {
            if (name != desc.name) continue;
            known = true;
            EXPECT_EQ(where, std::make_pair(desc.set, desc.binding)) << name;
          }
          EXPECT_TRUE(known) << "sampler " << name << " is not in shader_abi.h's tables";
        }
      }
      Reflection vs = reflect(spirv(v, facet::package::Stage::Vertex));
      for (const auto& [name, location] : vs.inputs) {
        ASSERT_EQ(name.rfind("a_", 0), 0u) << name;
        EXPECT_EQ(facet::abi::vertexAttribute(location).name, name.substr(2)) << name;
      }
    }
  }
}

TEST(ShaderAbi, MaterialParamsLayoutMatchesThePackageRecord) {
  for (const std::string& path : facet::test::exampleMaterials()) {
    SCOPED_TRACE(path);
    auto built = facet::test::buildFile(path);
    ASSERT_TRUE(built);
    const auto& info = built->package.material;
    Reflection fs = reflect(spirv(highDir1(*built), facet::package::Stage::Fragment));
    ASSERT_TRUE(fs.blocks.count("MaterialParams"));
    const Block& block = fs.blocks.at("MaterialParams");
    EXPECT_EQ(block.binding, facet::abi::kMaterialBinding);
    // SPIR-V's declared size ends at the last member; std140 rounds the buffer up to 16. With
    // a preshader the block goes on with the derived members, each where the program stores it.
    const facet::package::Preshader& preshader = built->package.preshader;
    EXPECT_EQ((block.size + 15) / 16 * 16, preshader.programs.empty() ? info.paramBlockSize : preshader.blockSize);
    std::set<uint32_t> stored, derived;
    for (const facet::package::PreshaderProgram& program : preshader.programs)
      for (uint32_t v : program.variants)
        if (built->package.variants[v].key == "high.dir1")
          for (const facet::package::PreshaderOp& op : program.ops)
            if (op.code == facet::package::PreshaderOpcode::Store) stored.insert(op.offset);
    for (const auto& [name, offset] : block.offsets)
      if (name.rfind("facet_", 0) == 0 && name.rfind("facet_pad", 0) != 0) derived.insert(offset);
    EXPECT_EQ(stored, derived);
    for (const auto& p : info.params) {
      if (p.size == 0) {
        EXPECT_EQ(block.offsets.count(p.name), 0u) << p.name << " is unused but has a uniform";
      } else {
        ASSERT_EQ(block.offsets.count(p.name), 1u) << p.name;
        EXPECT_EQ(block.offsets.at(p.name), p.offset) << p.name;
      }
    }
  }
}

// "Model only what a material needs": what the surface program does not read costs no uniform,
// no attribute and no varying in the shipped SPIR-V.
TEST(ShaderAbi, UnreadParameterHasNoUniformMember) {
  auto built = facet::test::buildText(R"(material m {
    param used: float = 0.5
    param unused: vec3 = vec3(1.0)
    surface { roughness = params.used }
})");
  ASSERT_TRUE(built);
  Reflection fs = reflect(spirv(highDir1(*built), facet::package::Stage::Fragment));
  const Block& block = fs.blocks.at("MaterialParams");
  // Besides the parameter, the block has the compiler's own facet_* members (the preshader's).
  EXPECT_EQ(std::count_if(block.offsets.begin(), block.offsets.end(),
                          [](const auto& m) { return m.first.rfind("facet_", 0) != 0; }),
            1);
  EXPECT_EQ(block.offsets.count("unused"), 0u);
  EXPECT_EQ(built->package.material.paramBlockSize, 16u);
  EXPECT_EQ(built->package.material.params.at(1).size, 0u);  // recorded, but with no slot
}

TEST(ShaderAbi, MaterialReadingNoParameterHasNoParameterBlock) {
  auto built = facet::test::buildText(R"(material m {
    param unused: float = 0.5
    surface { roughness = 0.25 }
})");
  ASSERT_TRUE(built);
  Reflection fs = reflect(spirv(highDir1(*built), facet::package::Stage::Fragment));
  EXPECT_EQ(fs.blocks.count("MaterialParams"), 0u);
  EXPECT_EQ(built->package.material.paramBlockSize, 0u);
}

// Each optional vertex input appears (attribute at its ABI location, and its varying) only in a
// material whose surface program needs it; a material without a normal map has no tangent.
TEST(ShaderAbi, OptionalVertexInputsExistOnlyWhenTheMaterialNeedsThem) {
  struct Case {
    const char* input;
    uint32_t location;
    const char* surface;  // a surface program that needs the input
  };
  const Case cases[] = {
      {"uv0", facet::abi::kAttribUv0, "roughness = fract(vertex.uv0.x * 4.0)"},
      {"uv1", facet::abi::kAttribUv1, "roughness = fract(vertex.uv1.y * 4.0)"},
      {"color", facet::abi::kAttribColor, "baseColor = vertex.color.rgb"},
      {"tangent", facet::abi::kAttribTangent, "normal = normalize(vec3(0.2, 0.1, 1.0))"},
  };
  auto without = facet::test::buildText("material m { surface { roughness = 0.5 } }");
  ASSERT_TRUE(without);
  Reflection noneVs = reflect(spirv(highDir1(*without), facet::package::Stage::Vertex));
  Reflection noneFs = reflect(spirv(highDir1(*without), facet::package::Stage::Fragment));
  EXPECT_EQ(noneVs.inputs.size(), 5u);  // a_position, a_normal, a_instanceRow0..2
  for (const Case& c : cases) {
    SCOPED_TRACE(c.input);
    const std::string attribute = std::string("a_") + c.input, varying = std::string("v_") + c.input;
    EXPECT_EQ(noneVs.inputs.count(attribute), 0u);
    EXPECT_EQ(noneFs.inputs.count(varying), 0u);
    auto with = facet::test::buildText(std::string("material m { surface { ") + c.surface + " } }");
    ASSERT_TRUE(with);
    Reflection vs = reflect(spirv(highDir1(*with), facet::package::Stage::Vertex));
    Reflection fs = reflect(spirv(highDir1(*with), facet::package::Stage::Fragment));
    ASSERT_EQ(vs.inputs.count(attribute), 1u);
    EXPECT_EQ(vs.inputs.at(attribute), c.location);
    EXPECT_EQ(vs.inputs.size(), 6u) << "only the one input is added";
    EXPECT_EQ(fs.inputs.count(varying), 1u);
  }
}

// A normal map samples a texture(normal) and writes `normal`; an unlit material never shades with
// a normal, so writing one there adds no tangent either.
TEST(ShaderAbi, NormalMapNeedsTangentsOnlyWhenLit) {
  const char* lit = R"(material m {
    param bumps: texture(normal) = vec4(0.5, 0.5, 1.0, 1.0)
    surface { normal = sample(params.bumps, vertex.uv0) }
})";
  const char* unlit = R"(material m {
    shading unlit
    param bumps: texture(normal) = vec4(0.5, 0.5, 1.0, 1.0)
    surface { normal = sample(params.bumps, vertex.uv0) baseColor = vec3(1.0) }
})";
  auto a = facet::test::buildText(lit), b = facet::test::buildText(unlit);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->package.material.params.at(0).type, facet::package::ParamType::TextureNormal);
  EXPECT_EQ(reflect(spirv(highDir1(*a), facet::package::Stage::Vertex)).inputs.count("a_tangent"), 1u);
  EXPECT_EQ(materialSamplers(reflect(spirv(highDir1(*a), facet::package::Stage::Fragment))), 1u);
  EXPECT_EQ(reflect(spirv(highDir1(*b), facet::package::Stage::Vertex)).inputs.count("a_tangent"), 0u);
  EXPECT_EQ(reflect(spirv(highDir1(*b), facet::package::Stage::Fragment)).samplers.size(), 0u);  // unlit: no IBL either
}

TEST(ShaderAbi, SampledTextureGetsASamplerAtItsSlotAndAnUnsampledOneNone) {
  auto built = facet::test::buildText(R"(material m {
    param unused: texture(linear) = vec4(0.5)
    param albedo: texture(srgb) = vec4(1.0)
    surface { baseColor = sample(params.albedo, vertex.uv0).rgb }
})");
  ASSERT_TRUE(built);
  const auto& params = built->package.material.params;
  EXPECT_EQ(params.at(0).type, facet::package::ParamType::TextureLinear);
  EXPECT_EQ(params.at(0).offset, facet::package::kNoTextureSlot);
  EXPECT_EQ(params.at(1).type, facet::package::ParamType::TextureSrgb);
  EXPECT_EQ(params.at(1).offset, 0u);
  EXPECT_EQ(built->package.material.paramBlockSize, 0u);  // no numbers read: no block

  // The fragment stage's material samplers: exactly one, at set 1, binding 8 + slot 0 (the
  // frame's IBL samplers are checked by IblSamplersAreDeclaredAtTheirBindingsOnlyWhereSampled).
  Reflection fs = reflect(spirv(highDir1(*built), facet::package::Stage::Fragment));
  ASSERT_EQ(materialSamplers(fs), 1u);
  ASSERT_EQ(fs.samplers.count("facet_material_albedo"), 1u);
  EXPECT_EQ(fs.samplers.at("facet_material_albedo").first, facet::abi::kTextureSet);
  EXPECT_EQ(fs.samplers.at("facet_material_albedo").second, facet::abi::kMaterialTextureBase);
}

// The uniform member of a parameter whose declared range exceeds fp16 is highp in the mediump
// tiers' fragment stage; one declared within it takes the tier's mediump.
TEST(ShaderAbi, ParameterRangedBeyondFp16IsAHighpUniform) {
  auto built = facet::test::buildText(R"(material m {
    param distance: float = 1000.0 in [0, 100000]
    param scale: float = 0.5 in [0, 1]
    surface { roughness = saturate(params.distance / 200000.0 + params.scale) }
})");
  ASSERT_TRUE(built);
  int checked = 0;
  for (const auto& s : highDir1(*built).shaders) {
    if (s.target != facet::package::Target::GlslEs300 || s.stage != facet::package::Stage::Fragment) continue;
    ++checked;
    std::string glsl(s.code.begin(), s.code.end());
    EXPECT_NE(glsl.find("\nhighp float distance;"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("\nmediump float scale;"), std::string::npos) << glsl;
  }
  EXPECT_EQ(checked, 1);
}

// The `lut` tier's table: a sampler at set 1, binding kSpecularLutBinding, named as the runtime
// binds it in GL, in the variants the package lists for it, and in no other.
TEST(ShaderAbi, SpecularLutSamplerIsAtItsAbiSlotInTheVariantsThatSampleIt) {
  EXPECT_STREQ(facet::compiler::kSpecularLutSamplerName, facet::abi::kSpecularLutName);
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  ASSERT_EQ(built->package.textures.size(), 1u);
  const auto& lut = built->package.textures[0];
  for (uint32_t i = 0; i < built->package.variants.size(); ++i) {
    const auto& variant = built->package.variants[i];
    SCOPED_TRACE(variant.key);
    Reflection fs = reflect(spirv(variant, facet::package::Stage::Fragment));
    bool listed = std::find(lut.variants.begin(), lut.variants.end(), i) != lut.variants.end();
    EXPECT_EQ(fs.samplers.count(facet::abi::kSpecularLutName), listed ? 1u : 0u);
    EXPECT_EQ(listed, variant.key == "low.dir1");
    if (!listed) continue;
    EXPECT_EQ(fs.samplers.at(facet::abi::kSpecularLutName).first, facet::abi::kTextureSet);
    EXPECT_EQ(fs.samplers.at(facet::abi::kSpecularLutName).second, facet::abi::kSpecularLutBinding);
  }
}

// The image-based lighting textures sit where the runtime binds them (shader_abi.h): the
// environment in every lit variant, the DFG table only in split-sum variants (every tier as
// shipped; here mid is also built with the analytic model, which has no table),
// and none of them in the vertex stage (vertex-diffuse tiers evaluate SH from the frame block).
TEST(ShaderAbi, IblSamplersAreDeclaredAtTheirBindingsOnlyWhereSampled) {
  EXPECT_EQ(facet::compiler::kEnvironmentLevels, facet::abi::kEnvironmentLevels);
  facet::compiler::BuildOptions analyticMid;
  analyticMid.adjustTier = [](facet::permutations::Tier tier, facet::permutations::TierConfig* config) {
    if (tier != facet::permutations::Tier::Mid) return;
    config->ambient = facet::permutations::AmbientModel::Analytic;
    config->energyCompensation = false;
  };
  const std::pair<uint32_t, uint32_t> environment{facet::abi::kTextureSet, facet::abi::kEnvironmentBinding};
  const std::pair<uint32_t, uint32_t> dfg{facet::abi::kTextureSet, facet::abi::kDfgLutBinding};
  for (bool shipped : {true, false}) {
    auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"),
                                        shipped ? facet::compiler::BuildOptions{} : analyticMid);
    ASSERT_TRUE(built);
    for (const auto& v : built->package.variants) {
      SCOPED_TRACE(v.key + (shipped ? " as shipped" : " with mid analytic"));
      Reflection fs = reflect(spirv(v, facet::package::Stage::Fragment));
      Reflection vs = reflect(spirv(v, facet::package::Stage::Vertex));
      ASSERT_TRUE(fs.samplers.count(facet::abi::kEnvironmentName));
      EXPECT_EQ(fs.samplers.at(facet::abi::kEnvironmentName), environment);
      const bool splitSum = shipped || v.key.rfind("mid.", 0) != 0;
      EXPECT_EQ(fs.samplers.count(facet::abi::kDfgLutName), splitSum ? 1u : 0u);
      if (splitSum) {
        EXPECT_EQ(fs.samplers.at(facet::abi::kDfgLutName), dfg);
      }
      EXPECT_TRUE(vs.samplers.empty());
      EXPECT_EQ(vs.blocks.at("FrameUniforms").size, facet::abi::kFrameBlockSh3Size);
    }
  }
}

// A Metal app binds fixed slots: the MSL of every variant of every example material declares
// each block and sampler at one slot, the one the package records (section MSLB) and shader_abi.h
// gives. Before the slots were pinned, facet_environment was texture(0) in red_plastic.high.dir1
// and texture(2) / texture(3) in painted_tiles' variants.
TEST(ShaderAbi, MslSlotOfEverySamplerAndBlockIsTheSameInEveryVariantAndMaterial) {
  // "constant FrameUniforms& frame [[buffer(1)]]", "texture2d<half> name [[texture(2)]]",
  // "sampler nameSmplr [[sampler(2)]]".
  const std::regex buffer(R"((\w+)& \w+ \[\[buffer\((\d+)\)\]\])");
  const std::regex texture(R"((\w+) \[\[texture\((\d+)\)\]\])");
  const std::regex sampler(R"((\w+)Smplr \[\[sampler\((\d+)\)\]\])");
  std::map<std::pair<std::string, std::string>, uint32_t> everywhere;  // (kind, name) -> slot, over all materials
  size_t declarations = 0;
  for (const std::string& path : facet::test::exampleMaterials()) {
    auto built = facet::test::buildFile(path);
    ASSERT_TRUE(built);
    std::map<std::pair<std::string, std::string>, uint32_t> recorded;
    for (const facet::package::MslBinding& b : built->package.mslBindings) {
      if (b.kind == facet::package::MslResource::Buffer) {
        recorded[{"buffer", b.name}] = b.index;
        EXPECT_EQ(b.binding, b.index) << b.name;
      } else {
        recorded[{"texture", b.name}] = b.index;
        recorded[{"sampler", b.name}] = b.index;
      }
    }
    ASSERT_EQ(recorded.at({"buffer", "FrameUniforms"}), facet::abi::mslBufferIndex(facet::abi::kFrameBlock));
    for (const auto& v : built->package.variants) {
      for (const auto& shader : v.shaders) {
        if (shader.target != facet::package::Target::Msl) continue;
        SCOPED_TRACE(path + " " + v.key + " " + facet::package::toString(shader.stage));
        const std::string msl(shader.code.begin(), shader.code.end());
        using Pattern = std::pair<const char*, const std::regex*>;
        for (auto [kind, pattern] :
             {Pattern{"buffer", &buffer}, Pattern{"texture", &texture}, Pattern{"sampler", &sampler}}) {
          for (std::sregex_iterator it(msl.begin(), msl.end(), *pattern), end; it != end; ++it) {
            const std::pair<std::string, std::string> resource{kind, (*it)[1].str()};
            const uint32_t slot = uint32_t(std::stoul((*it)[2].str()));
            ++declarations;
            ASSERT_TRUE(recorded.count(resource))
                << kind << " " << resource.second << " is not in the package's record";
            EXPECT_EQ(slot, recorded.at(resource)) << kind << " " << resource.second;
            // The three vertex streams take buffers kMslVertexBufferIndex + stream (28..30): no
            // block may sit there.
            if (std::string(kind) == "buffer") {
              EXPECT_LT(slot, facet::abi::mslVertexBufferIndex(0)) << resource.second;
            }
            auto known = everywhere.emplace(resource, slot).first;
            EXPECT_EQ(known->second, slot) << kind << " " << resource.second << " moved between materials";
          }
        }
      }
    }
  }
  EXPECT_GT(declarations, 0u);
  EXPECT_EQ(everywhere.at({"texture", facet::abi::kEnvironmentName}), facet::abi::kEnvironmentBinding);
  EXPECT_EQ(everywhere.at({"sampler", facet::abi::kEnvironmentName}), facet::abi::kEnvironmentBinding);
  EXPECT_EQ(everywhere.at({"buffer", "MaterialParams"}), facet::abi::kMaterialBinding);
}

// The irradiance cube's Metal slot is listed only by a package whose variants read it (a tier with
// the `cube` diffuse): every other lit package keeps the slots, and bytes, it had before the cube,
// and a package built before it still passes the loader's check.
TEST(ShaderAbi, OnlyAPackageReadingTheIrradianceCubeListsItsMetalSlot) {
  const std::string path = facet::test::examplePath("materials/red_plastic.mat");
  const std::string text = facet::test::readText(path);
  const auto listsIrradiance = [](const facet::package::Package& p) {
    return std::any_of(p.mslBindings.begin(), p.mslBindings.end(),
                       [](const facet::package::MslBinding& b) { return b.name == facet::abi::kIrradianceName; });
  };
  auto plain = facet::test::buildText(text, path);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(listsIrradiance(plain->package));
  EXPECT_EQ(facet::package::semanticError(plain->package), "");

  const size_t end = text.rfind('}');
  ASSERT_NE(end, std::string::npos);
  auto cube = facet::test::buildText(text.substr(0, end) + "    tier high { diffuse = cube }\n}\n", path);
  ASSERT_TRUE(cube);
  EXPECT_TRUE(listsIrradiance(cube->package));
  EXPECT_EQ(facet::package::semanticError(cube->package), "");
  bool declared = false;
  for (const auto& v : cube->package.variants)
    for (const auto& shader : v.shaders)
      if (shader.target == facet::package::Target::Msl && shader.stage == facet::package::Stage::Fragment) {
        const std::string msl(shader.code.begin(), shader.code.end());
        const bool reads = msl.find(std::string(facet::abi::kIrradianceName) + " [[texture(" +
                                    std::to_string(facet::abi::kIrradianceBinding) + ")]]") != std::string::npos;
        EXPECT_EQ(reads, v.key.rfind("high.", 0) == 0) << v.key;
        declared = declared || reads;
      }
  EXPECT_TRUE(declared);
}
