// The binary interface between the shaders in a package and the runtime that draws with them:
// one owner (library facet_shader_abi, header only), included by the compiler, which prints the
// shaders' declarations from the tables at the end of this file, and by the runtime, which binds
// by the same numbers. tests/compiler/test_shader_abi.cpp reflects compiled SPIR-V and checks it against
// these tables and the C++ structs, so a change to one side fails the tests, not a frame on a phone.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace facet::abi {

// Vertex inputs, in two streams (vertex buffer bindings): binding kPositionStream holds positions
// only, binding kAttributeStream every other attribute. A tiler's binning pass runs a
// position-only vertex shader and a shadow or depth pass reads positions only: with positions in
// their own stream neither fetches the rest (S. Aaltonen, "HypeHype Mobile Rendering
// Architecture", SIGGRAPH 2023: positions in their own stream, vertices packed 2.16x smaller). The
// runtime packs each mesh at upload (runtime/vertex_packing.h: 16-bit normalized positions and
// UVs, 10:10:10:2 normals and tangents, unorm8 colours, or fp32 everywhere as the reference);
// the formats are pipeline state, so every shader declares the same `in highp vecN a_<name>` and
// decodes positions and UVs with one FMA each from ObjectUniforms (positionScale, ...). A shader
// declares only the locations its material reads (the compiler derives them), so an unread
// attribute costs memory bandwidth in the fetch but no shader work.
inline constexpr uint32_t kPositionStream = 0;
inline constexpr uint32_t kAttributeStream = 1;
inline constexpr uint32_t kVertexStreams = 2;  // the mesh's streams; the instance stream follows
// Per-instance transforms: binding kInstanceStream, advanced once per instance (Vulkan
// VK_VERTEX_INPUT_RATE_INSTANCE, GLES 3.0 glVertexAttribDivisor 1), so N objects that differ only
// in their transform are one draw (Aaltonen 2023 above: instanced draws with 4×3 matrices). A
// vertex stream rather than a uniform array: GLES 3.0 has no storage buffers and a uniform
// block may be as small as 16 KB (341 transforms), while an attribute stream has no such bound.
// Every forward variant reads it (a draw of one object is one instance): no variant axis, so no
// doubled package, and the three vec4 fetches replace the mat4 model matrix the uniform block held.
inline constexpr uint32_t kInstanceStream = 2;
inline constexpr uint32_t kStreams = 3;  // bindings 0..kStreams-1: two of the mesh, one of instances

inline constexpr uint32_t kAttribPosition = 0;      // vec3, object space
inline constexpr uint32_t kAttribNormal = 1;        // vec3, object space, unit length
inline constexpr uint32_t kAttribUv0 = 2;           // vec2
inline constexpr uint32_t kAttribUv1 = 3;           // vec2
inline constexpr uint32_t kAttribColor = 4;         // vec4, linear RGBA in [0, 1]
inline constexpr uint32_t kAttribTangent = 5;       // vec4: xyz object-space unit tangent (direction of
                                                    // +u), w = ±1 bitangent sign (MikkTSpace convention:
                                                    // bitangent = w · cross(normal, tangent))
inline constexpr uint32_t kAttribInstanceRow0 = 6;  // vec4 each: rows 0..2 of the instance's 4×3
inline constexpr uint32_t kAttribInstanceRow1 = 7;  // object-to-world matrix (InstanceTransform)
inline constexpr uint32_t kAttribInstanceRow2 = 8;
// The authoring form of a vertex (runtime::Mesh, runtime::Vertex): 18 floats in the order of
// kVertexAttributes' offsetFloats, which the runtime packs into the two streams.
inline constexpr uint32_t kVertexFloats = 18;
inline constexpr uint32_t kVertexStride = kVertexFloats * sizeof(float);
// Every attribute: location, float components the shader reads, float offset within an authoring
// vertex, the stream that carries it, and its name: the shaders declare `in highp vecN a_<name>`
// (N = components). Both backends describe the streams from this table and the packing's
// formats; the compiler declares the inputs from it.
struct VertexAttribute {
  uint32_t location;
  uint32_t components;
  uint32_t offsetFloats;
  uint32_t stream;
  std::string_view name;
};
inline constexpr VertexAttribute kVertexAttributes[] = {
    {kAttribPosition, 3, 0, kPositionStream, "position"}, {kAttribNormal, 3, 3, kAttributeStream, "normal"},
    {kAttribUv0, 2, 6, kAttributeStream, "uv0"},          {kAttribUv1, 2, 8, kAttributeStream, "uv1"},
    {kAttribColor, 4, 10, kAttributeStream, "color"},     {kAttribTangent, 4, 14, kAttributeStream, "tangent"},
};
// The instance stream: one InstanceTransform per instance, fp32, its rows at offsetFloats 0, 4, 8.
inline constexpr VertexAttribute kInstanceAttributes[] = {
    {kAttribInstanceRow0, 4, 0, kInstanceStream, "instanceRow0"},
    {kAttribInstanceRow1, 4, 4, kInstanceStream, "instanceRow1"},
    {kAttribInstanceRow2, 4, 8, kInstanceStream, "instanceRow2"},
};
constexpr const VertexAttribute& vertexAttribute(uint32_t location) {
  for (const VertexAttribute& a : kVertexAttributes)
    if (a.location == location) return a;
  for (const VertexAttribute& a : kInstanceAttributes)
    if (a.location == location) return a;
  return kVertexAttributes[0];  // unreachable for the kAttrib* constants (a static_assert below checks them)
}

// Uniform blocks, std140. Vulkan: descriptor set 0, binding = the value below.
// GLES 3.00 has no layout(binding): the runtime looks the block up by name and calls
// glUniformBlockBinding(program, index, value). A block a shader does not use may be absent.
inline constexpr uint32_t kFrameBinding = 0;     // block "FrameUniforms"
inline constexpr uint32_t kObjectBinding = 1;    // block "ObjectUniforms"
inline constexpr uint32_t kMaterialBinding = 2;  // block "MaterialParams" (layout recorded in the package)
// block "ShadowUniforms", shadow receivers only (.sh variants); 3 is the post pass's binding point
// in GL, which shares binding points across programs.
inline constexpr uint32_t kShadowBinding = 4;

// Textures: combined image samplers. Vulkan: descriptor set 1 (set 0 holds the uniform blocks),
// binding = the value below; GL: texture unit = the same value, and the sampler uniform is found
// by the name the DrawItem / FrameDesc gives.
//   0..7   frame textures, shared by every draw (lookup tables, environment)
//   8..15  the material's texture parameters, in declaration order (kMaterialTextureBase + i)
inline constexpr uint32_t kTextureSet = 1;
inline constexpr uint32_t kDfgLutBinding = 0;       // "facet_dfgLut": split-sum DFG terms
inline constexpr uint32_t kSpecularLutBinding = 1;  // "facet_specularLut": low-tier specular LUT (from the package)
inline constexpr uint32_t kEnvironmentBinding = 2;  // "facet_environment": prefiltered radiance, mip = roughness
inline constexpr uint32_t kShadowAtlasBinding = 3;  // "facet_shadowAtlas": the sun's depth atlas, compare sampler
inline constexpr uint32_t kIrradianceBinding = 4;   // "facet_irradiance": diffuse irradiance / π, the `cube` diffuse
inline constexpr const char* kSpecularLutName = "facet_specularLut";
// The specular table's size, R8: chunks/specular_lut.glsl addresses its texel centres with these
// numbers, so the runtime refuses a package table of any other shape (even one of the same bytes).
inline constexpr uint32_t kSpecularLutWidth = 128;
inline constexpr uint32_t kSpecularLutHeight = 64;
inline constexpr const char* kDfgLutName = "facet_dfgLut";            // RGBA16F 64×64, one level (docs/ibl.md layout)
inline constexpr const char* kEnvironmentName = "facet_environment";  // RGBA16F cube map, kEnvironmentLevels levels
// Levels of the prefiltered environment: level m holds perceptual roughness r_m with
// r_m (2 − r_m) = m / (levels − 1), so the shaders read lod = r (2 − r) × (kEnvironmentLevels − 1)
// (chunks/ibl_prefiltered.glsl).
inline constexpr uint32_t kEnvironmentLevels = 5;
// The irradiance cube of the `cube` diffuse (chunks/ambient_irradiance_cube.glsl): SH3's
// irradiance / π, the frame block's sh[0..8] evaluated at each texel's centre direction (negative
// lobes clamped to 0, as the SH sum is), RGBA16F, one level of kIrradianceMapSize² a face,
// bilinear across faces (runtime::irradianceTexture).
inline constexpr const char* kIrradianceName = "facet_irradiance";
inline constexpr uint32_t kIrradianceMapSize = 32;
inline constexpr uint32_t kShCoefficients = 9;  // SH3; SH2 variants read the first 4
// With band 4 (TierConfig::shBands 5, an option no preset selects) the frame block's sh array
// holds 9 more: band 4's, after SH3's (band 3's are zero under the clamped cosine, not stored).
// Every other variant declares the block with the first kShCoefficients only, a prefix of the
// same buffer, so its shaders and their uniform count are those of SH3.
inline constexpr uint32_t kShBand4Coefficients = 9;
inline constexpr uint32_t kShFrameCoefficients = kShCoefficients + kShBand4Coefficients;
inline constexpr uint32_t kMaterialTextureBase = 8;
inline constexpr uint32_t kMaxMaterialTextures = 8;
// A material texture's sampler uniform is this prefix + the parameter's name. The `facet_`
// namespace is the interface's: no chunk or template declares a name in it, so no parameter name
// can collide with a chunk function (a texture `f0` once became `material_f0`, a chunk function).
// ir/src/emit_glsl.cpp and compiler/src/assemble.cpp write the same prefix.
inline constexpr const char* kMaterialSamplerPrefix = "facet_material_";

// Post pass: the HDR colour of the forward pass, as a combined image sampler at set 0 binding 0
// (Vulkan) or texture unit 0 (GL, uniform "hdrColor").
inline constexpr uint32_t kPostHdrBinding = 0;
// Colour grading (post variants with grading only): a 3D lookup table of kColorLutSize³ RGBA16F
// texels, trilinear, clamped; set kPostHdrSet binding kPostColorLutBinding (Vulkan), texture unit
// kPostColorLutBinding (GL), [[texture(kPostColorLutBinding)]] (Metal). Texel (r, g, b) holds the
// graded sRGB-encoded colour of the input (r, g, b) / (N − 1) (runtime/color_grading.h).
inline constexpr uint32_t kPostColorLutBinding = 1;
inline constexpr const char* kPostColorLutName = "facet_colorLut";
inline constexpr uint32_t kColorLutSize = 32;
// The post pass's uniform block (post variants with a vignette only): Vulkan set kPostHdrSet,
// binding kPostUniformsBinding; GL uniform buffer binding point kPostUniformsBinding (clear of the
// forward blocks' 0..2); Metal [[buffer(kPostUniformsBinding)]].
inline constexpr uint32_t kPostUniformsBinding = 3;
// Bloom (post variants with bloom only): the bloom chain's finest level, RGBA16F or the HDR format,
// a quarter of the output's pixels, sampled bilinearly and clamped at the output pixel's centre;
// set kPostHdrSet binding kPostBloomBinding (Vulkan), texture unit kPostBloomBinding (GL),
// [[texture(kPostBloomBinding)]] (Metal).
inline constexpr uint32_t kPostBloomBinding = 2;
inline constexpr const char* kPostBloomName = "facet_bloom";

// Per-frame data. Matrices are column-major, OpenGL clip conventions (right-handed world,
// clip y up, clip z in [-w, w]); the Vulkan backend converts to its own clip space.
//
// Lighting contract (Filament's mobile practice, see docs/lighting-units.md): the CPU multiplies
// every light by the camera exposure before upload, so the shader sees values near 1 even for a
// 110 000 lux sun, and mediump (fp16, max 65504) never overflows on light intensities.
// One punctual (point or spot) light, four vec4s (chunks/light_punctual.glsl reads it). A point
// light has spotScaleOffset = (0, 1): its cone factor is 1 in every direction.
struct PunctualLightUniforms {
  float positionFalloff[4];  // xyz: world-space position; w: 1 / range² (the falloff window's scale)
  float colorIntensity[4];   // rgb: colour × intensity (candela) × exposure; w: unused
  float direction[4];        // xyz: spot axis, unit vector the light travels along; w: unused
  float spotScaleOffset[4];  // x: 1 / (cos inner − cos outer); y: −cos outer · x; zw: unused
};
static_assert(sizeof(PunctualLightUniforms) == 64, "std140 layout of PunctualLightUniforms");

// Punctual lights in the frame block. A variant with N of them (VariantKey pointLights) reads
// entries 0..N-1 at fixed offsets; the runtime zeroes the rest.
inline constexpr uint32_t kMaxPunctualLights = 4;

struct FrameUniforms {
  float viewProjection[16];
  float cameraPosition[4];  // xyz: world-space eye position; w: 1 when masked materials write their
                            // edge coverage as alpha for alpha to coverage (MSAA on), else 0: set
                            // by the backend, whatever the app wrote (output_blending.glsl)
  float lightDirection[4];  // xyz: unit vector from the surface towards the light; w: unused.
                            // Unit length is a guarantee the shaders rely on (they no longer
                            // normalize it per pixel): SceneFrame normalizes the scene's sun; an
                            // app filling the block itself must normalize too
  float lightColor[4];      // rgb: colour × illuminance (lux) × exposure; w: unused. In a shadow view's
                            // block (the `.depth.slope` programs, docs/shadows.md "Bias"): the spot's
                            // position, w 1, or 0; lightDirection the view's axis and slope constant
  float ambient[4];         // rgb: the environment's mean radiance × exposure; w: unused. Not read by
                            // the forward shaders since image-based lighting (sh and the environment
                            // texture replace it); kept as the frame's clear colour and for apps' own shaders
  PunctualLightUniforms punctualLights[kMaxPunctualLights];
  // SH irradiance of the environment, pre-folded for the shader (facet::ibl::shaderIrradianceCoefficients:
  // irradiance / π = Σ sh[k] · p_k(n), docs/ibl.md) and pre-exposed; rgb used, w 0. Index
  // k = l(l + 1) + m; SH2 variants read 0..3 (the first four of an SH3 projection are the SH2 one).
  // Entries 9..17 are band 4's k = 16..24, read (and declared) by band-4 variants only.
  float sh[kShFrameCoefficients][4];
};
static_assert(sizeof(FrameUniforms) == 672, "std140 layout of FrameUniforms");
// What a variant without band 4 declares: the block up to SH3's last coefficient.
inline constexpr uint32_t kFrameBlockSh3Size = uint32_t(sizeof(FrameUniforms)) - 16 * kShBand4Coefficients;

// The sun's shadow, read by receiver variants (VariantKey shadowCascades > 0; docs/shadows.md), and
// a casting spot light's (spotShadows > 0).
// Every cascade is an orthographic view of the sun in its own rectangle of one square depth atlas,
// so all of them share one rotation: the vertex stage takes the position into the sun's frame once
// (lightView: x, y across the rays, z along them, metres), and cascade i is a scale and an offset
// of it, (atlas u, atlas v, depth) = light · cascadeScale[i].xyz + cascadeOffset[i].xyz, with u, v
// in [0, 1] over the whole atlas (the rectangle folded in) and depth in [0, 1] as the atlas stores
// it, 0 nearest the sun: the same numbers for Vulkan and GL (a depth texture holds window depth in
// [0, 1] in both). All of it highp in the shaders: an atlas coordinate needs 1/4096 of a texel
// step at 8192² (fp16 has 1/2048 of 1), a depth 1/65536 (a D16 step).
inline constexpr uint32_t kMaxShadowCascades = 4;
struct ShadowUniforms {
  float lightView[16];  // column-major, world → the sun's frame (metres); only its top three rows are read
  float cascadeScale[kMaxShadowCascades][4];   // xyz: the sun's frame → atlas scale; w: normal offset, metres
  float cascadeOffset[kMaxShadowCascades][4];  // xyz: the offset; w: unused
  // The view depth (metres along the camera's forward axis) at which cascade i ends: a position
  // takes the first cascade whose split lies beyond it. Entries past the scene's cascades repeat
  // the last one's (and cascades past it repeat its scale and offset).
  float splits[4];
  float cameraForward[4];  // xyz: the camera's unit forward axis; w: unused
  // x, y: visibility fades to 1 as clamp(viewDepth · x + y, 0, 1) goes from 0 to 1 (the shadow
  // distance's fade); z: the atlas's texels per side; w: 1 / z.
  float fadeAtlas[4];
  // The casting spot light's view (light slot 0; `.sp1` receivers, docs/shadows.md "Spot
  // shadows"): world → atlas (u·w, v·w, depth·w, w), its cell and window depth folded in, w the
  // distance along the light's axis; a receiver divides by w in highp.
  float spotAtlasFromWorld[16];
  // x: the normal offset per metre of distance along the axis (normalBias × the view's texel width
  // at 1 m; a texel at distance w is w times as wide); yzw: unused.
  float spotNormalOffset[4];
};
static_assert(sizeof(ShadowUniforms) == 320, "std140 layout of ShadowUniforms");

// One instance's object-to-world transform: the top three rows of the column-major 4×4 model
// matrix (the fourth is 0 0 0 1 for an affine transform), row r = (m[0][r], m[1][r], m[2][r],
// m[3][r]); world = (dot(row0, p), dot(row1, p), dot(row2, p)) for p = (object position, 1).
// 48 bytes where a mat4 and its normal matrix took 128: the forward vertex stage derives the
// normal's transform from these rows (templates/forward.vert.glsl).
struct InstanceTransform {
  float rows[3][4];
};
static_assert(sizeof(InstanceTransform) == 48, "three vec4 attributes");
// Bounds on instances, from memory: 64 Ki per draw is 3 MiB of transforms, and the frame's
// 256 Ki (12 MiB) are copied into a buffer per frame in flight (8 at most: 96 MiB). A scene
// holds far fewer objects (scene/scene.h); an app past them splits its draws or frames.
inline constexpr uint32_t kMaxInstancesPerDraw = 64 * 1024;
inline constexpr uint32_t kMaxInstancesPerFrame = 256 * 1024;

// Per-draw data: how the mesh decodes. The transform is per instance (InstanceTransform).
struct ObjectUniforms {
  // How the mesh's streams decode (runtime/vertex_packing.h), written by the backend from the
  // mesh it draws (whatever a DrawItem holds here is replaced): object-space position =
  // a_position · positionScale.xyz + positionOffset.xyz, uvN = a_uvN · uvNScaleOffset.xy +
  // uvNScaleOffset.zw, one FMA each. (1, 1, 1) and 0 for fp32 streams.
  float positionScale[4];
  float positionOffset[4];
  float uv0ScaleOffset[4];
  float uv1ScaleOffset[4];
};
static_assert(sizeof(ObjectUniforms) == 64, "std140 layout of ObjectUniforms");

// Per-frame data of the post pass (block "PostUniforms", chunks/vignette.glsl reads it).
struct PostUniforms {
  // x: intensity (0: none, 1: black at the corners), y: radius where darkening starts, z: the
  // width of the transition, w: roundness (1: a circle on screen, 0: an ellipse fitting the frame).
  // Distances are in units of half the frame's height from its centre (runtime/post_uniforms.h).
  float vignette[4];
  float viewport[4];  // x: 1 / width, y: 1 / height (pixels), z: width / height, w: unused
  // Bloom (chunks/bloom.glsl): x: intensity in [0, 1], y: threshold (0: none), z: the soft knee's
  // half width, w: unused. Filled by the backend from its options whatever the frame says.
  float bloom[4];
};
static_assert(sizeof(PostUniforms) == 48, "std140 layout of PostUniforms");

// The environment drawn as the background (runtime/background.h): a draw of the forward pass whose
// "MaterialParams" block is this (templates/post_background.frag.glsl).
struct BackgroundParams {
  // Column-major: the world-space direction seen through a pixel is clipToDirection · (x, y, 1, 1)
  // for its GL normalized device coordinates x, y (unnormalized; only its top three rows are read).
  float clipToDirection[16];
  float lodIntensity[4];  // x: the environment's level (0: its base level), y: the radiance's factor
};
static_assert(sizeof(BackgroundParams) == 80, "std140 layout of BackgroundParams");

// ---------------------------------------------------------------------------------------------
// The interface as data. The compiler prints the shaders' declarations from these tables
// (compiler/src/assemble.cpp), the runtime binds by the same numbers, and the MSL backend pins
// Metal's argument slots from them (compiler/src/msl_backend.cpp), so every number above is
// written once. The same arrangement as Filament's filabridge (libs/filabridge: the uniform
// interface blocks and sampler bindings its material compiler generates from and its engine binds
// by), reduced to what Facet's shaders declare.

// A uniform block member, printed as `<type> <name>[arraySize];` (arraySize 0: not an array).
// Types carry their precision: a block shared by both stages must match member for member.
struct MemberDesc {
  std::string_view type;
  std::string_view name;
  uint32_t arraySize = 0;
};

// A struct type declared before the blocks that hold it.
struct StructDesc {
  std::string_view name;
  std::span<const MemberDesc> members;
};

// A std140 uniform block: Vulkan set/binding; GLES binds it by `name` (glUniformBlockBinding to
// `binding`). An empty `members` list means the members are the material's (package layout).
struct BlockDesc {
  std::string_view name;      // block type name, e.g. "FrameUniforms"
  std::string_view instance;  // the instance name the chunks read through, e.g. "frame"
  uint32_t set = 0;
  uint32_t binding = 0;
  std::span<const MemberDesc> members;
  uint32_t std140Size = 0;  // 0: the material's (MaterialInfo::paramBlockSize)
};

inline constexpr uint32_t kBlockSet = 0;

inline constexpr MemberDesc kPunctualLightMembers[] = {
    {"highp vec4", "positionFalloff"},
    {"highp vec4", "colorIntensity"},
    {"highp vec4", "direction"},
    {"highp vec4", "spotScaleOffset"},
};
inline constexpr StructDesc kPunctualLightStruct{"PunctualLightData", kPunctualLightMembers};

inline constexpr MemberDesc kFrameMembers[] = {
    {"highp mat4", "viewProjection"},
    {"highp vec4", "cameraPosition"},
    {"highp vec4", "lightDirection"},
    {"highp vec4", "lightColor"},
    {"highp vec4", "ambient"},
    {"PunctualLightData", "punctualLights", kMaxPunctualLights},
    {"highp vec4", "sh", kShCoefficients},
};
inline constexpr MemberDesc kObjectMembers[] = {
    {"highp vec4", "positionScale"},
    {"highp vec4", "positionOffset"},
    {"highp vec4", "uv0ScaleOffset"},
    {"highp vec4", "uv1ScaleOffset"},
};

// std140Size is what the runtime binds, the whole of FrameUniforms; a variant without band 4
// declares sh with kShCoefficients entries (kFrameBlockSh3Size bytes), a band-4 one with
// kShFrameCoefficients.
inline constexpr BlockDesc kFrameBlock{"FrameUniforms", "frame",       kBlockSet,
                                       kFrameBinding,   kFrameMembers, uint32_t(sizeof(FrameUniforms))};
inline constexpr BlockDesc kObjectBlock{"ObjectUniforms", "object",       kBlockSet,
                                        kObjectBinding,   kObjectMembers, uint32_t(sizeof(ObjectUniforms))};
inline constexpr BlockDesc kMaterialBlock{"MaterialParams", "params", kBlockSet, kMaterialBinding, {}, 0};
inline constexpr MemberDesc kShadowMembers[] = {
    {"highp mat4", "lightView"},
    {"highp vec4", "cascadeScale", kMaxShadowCascades},
    {"highp vec4", "cascadeOffset", kMaxShadowCascades},
    {"highp vec4", "splits"},
    {"highp vec4", "cameraForward"},
    {"highp vec4", "fadeAtlas"},
    {"highp mat4", "spotAtlasFromWorld"},
    {"highp vec4", "spotNormalOffset"},
};
inline constexpr BlockDesc kShadowBlock{"ShadowUniforms", "shadow",       kBlockSet,
                                        kShadowBinding,   kShadowMembers, uint32_t(sizeof(ShadowUniforms))};
inline constexpr BlockDesc kBlocks[] = {kFrameBlock, kObjectBlock, kMaterialBlock, kShadowBlock};

// A combined image sampler of the frame (every draw binds the same texture).
struct SamplerDesc {
  std::string_view name;
  uint32_t set = 0;
  uint32_t binding = 0;
  bool cube = false;    // samplerCube (the runtime binds a cube map there), else sampler2D
  bool shadow = false;  // sampler2DShadow: a depth texture read with a less-or-equal compare
};
inline constexpr SamplerDesc kDfgLutSampler{kDfgLutName, kTextureSet, kDfgLutBinding};
inline constexpr SamplerDesc kSpecularLutSampler{kSpecularLutName, kTextureSet, kSpecularLutBinding};
inline constexpr SamplerDesc kEnvironmentSampler{kEnvironmentName, kTextureSet, kEnvironmentBinding, true};
inline constexpr SamplerDesc kIrradianceSampler{kIrradianceName, kTextureSet, kIrradianceBinding, true};
inline constexpr SamplerDesc kFrameSamplers[] = {kDfgLutSampler, kSpecularLutSampler, kEnvironmentSampler,
                                                 kIrradianceSampler};
// The sun's shadow atlas (ShadowUniforms), receiver variants only: depth compare on, bilinear where
// the device filters depth (docs/shadows.md), clamped to the edge.
inline constexpr const char* kShadowAtlasName = "facet_shadowAtlas";
inline constexpr SamplerDesc kShadowAtlasSampler{kShadowAtlasName, kTextureSet, kShadowAtlasBinding, false, true};
// The material's texture parameter in sampler slot i: kMaterialSamplerPrefix + name, set
// kTextureSet, binding materialTextureBinding(i).
constexpr uint32_t materialTextureBinding(uint32_t slot) { return kMaterialTextureBase + slot; }

// Attachments of the forward pass and of the post pass that reads its colour. The forward pass
// writes `fragColor` (linear pre-exposed HDR, RGBA16F). The post pass reads it as `hdrColor`:
// merged path, input attachment 0 at set kPostHdrSet / binding kPostHdrBinding (Vulkan; Metal
// [[color(0)]]) or colour output 0 declared inout (GLES framebuffer fetch), LDR written to colour
// 1; separate path, a sampler at the same set and binding (GL: texture unit kPostHdrBinding), LDR
// written to colour 0. The post compiler (compiler/src/post.cpp) prints these declarations.
inline constexpr uint32_t kForwardColorLocation = 0;
inline constexpr std::string_view kPostHdrName = "hdrColor";
inline constexpr uint32_t kPostHdrSet = 0;
inline constexpr uint32_t kPostHdrInputAttachmentIndex = 0;
inline constexpr uint32_t kPostHdrColorLocation = 0;     // merged path: HDR is colour 0 of the pass
inline constexpr uint32_t kPostMergedLdrLocation = 1;    // merged path: LDR is colour 1
inline constexpr uint32_t kPostSeparateLdrLocation = 0;  // separate path: LDR is the only colour
// MSAA on the merged path with multisampled attachments: the post pass reads `hdrColor` as a
// subpassInputMS and loops over its samples; the count is this specialization constant of the
// fragment stage (`facet_postSamples`), set by the Vulkan backend when it builds the pipeline.
inline constexpr uint32_t kPostSampleCountConstantId = 0;
// The FXAA pass (after the post pass, when on) samples the post pass's tone-mapped RGBA8 image
// as `toneMapped` at set kPostHdrSet / binding kPostHdrBinding (GL: that texture unit), bilinear
// and clamped, and writes colour kPostSeparateLdrLocation.
inline constexpr std::string_view kFxaaInputName = "toneMapped";
// The bloom chain's passes (chunks/bloom.glsl) sample the level before as `bloomSource` at set
// kPostHdrSet / binding kPostHdrBinding (GL: that texture unit), bilinear and clamped; the
// threshold form reads the PostUniforms block; they write colour kPostSeparateLdrLocation.
inline constexpr std::string_view kBloomSourceName = "bloomSource";
// The post pass's block and grading sampler, at the HDR input's set.
inline constexpr MemberDesc kPostMembers[] = {
    {"mediump vec4", "vignette"},
    {"highp vec4", "viewport"},
    {"mediump vec4", "bloom"},
};
inline constexpr BlockDesc kPostBlock{"PostUniforms",       "post",       kPostHdrSet,
                                      kPostUniformsBinding, kPostMembers, uint32_t(sizeof(PostUniforms))};
inline constexpr SamplerDesc kPostColorLutSampler{kPostColorLutName, kPostHdrSet, kPostColorLutBinding};
// The background's parameters, bound where a material's are (the draw is a forward-pass draw).
inline constexpr MemberDesc kBackgroundMembers[] = {
    {"highp mat4", "clipToDirection"},
    {"highp vec4", "lodIntensity"},
};
inline constexpr BlockDesc kBackgroundBlock{"MaterialParams", "params",           kBlockSet,
                                            kMaterialBinding, kBackgroundMembers, uint32_t(sizeof(BackgroundParams))};

// Metal (MSL) argument slots, pinned by the MSL backend from the tables above so that every
// variant of every material uses the same ones (SPIRV-Cross otherwise numbers resources in order
// of use, per shader): a block at [[buffer(binding)]]; a sampler of set kTextureSet at
// [[texture(binding)]] and [[sampler(binding)]] (bindings 0..15 fit iOS's 16 samplers). The
// vertex streams (stage_in) should use buffer indices kMslVertexBufferIndex + stream (positions
// at 28, the other attributes at 29, instance transforms at 30; MTLVertexDescriptor's layouts),
// clear of the blocks.
// The package records these slots (section MSLB, docs/package-format.md).
constexpr uint32_t mslBufferIndex(const BlockDesc& block) { return block.binding; }
constexpr uint32_t mslTextureIndex(uint32_t textureBinding) { return textureBinding; }
inline constexpr uint32_t kMslVertexBufferIndex = 28;
constexpr uint32_t mslVertexBufferIndex(uint32_t stream) { return kMslVertexBufferIndex + stream; }
static_assert(mslVertexBufferIndex(kStreams - 1) <= 30, "Metal has buffer indices 0..30");

static_assert(vertexAttribute(kAttribTangent).location == kAttribTangent && vertexAttribute(kAttribUv0).components == 2,
              "kVertexAttributes lists every kAttrib* location");

}  // namespace facet::abi
