// The .matpkg format: what a compiled material ships to an app.
//
// A package holds one material: its metadata (parameters, uniform block layout) and, per
// variant, one shader per (stage, target). matc writes it; apps read it through the runtime.
// The byte layout is documented in docs/package-format.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facet::package {

// Format version major.minor (docs/package-format.md, "Format version"). A reader reads every
// minor of its own major up to its own minor; any other version is refused with a message naming
// both and the command that rebuilds the package. The writer stamps the lowest minor that
// describes the file, so packages that use no newer feature stay readable by older readers.
inline constexpr uint16_t kFormatMajor = 1;
inline constexpr uint16_t kFormatMinor = 8;  // 1.1: shader blobs compressed against a package dictionary;
                                             // 1.2: the Metal argument slots (section MSLB);
                                             // 1.3: the preshader (section PRSH);
                                             // 1.4: lit shaders sample the environment as a cube map;
                                             // 1.5: shaders read two packed vertex streams;
                                             // 1.6: and per-instance 4×3 transforms (stream 2);
                                             // 1.7: depth-only programs for the shadow pass;
                                             // 1.8: the preshader's div and sqrt ops
inline constexpr uint16_t kFirstMinorWithCubeEnvironment = 4;
inline constexpr uint16_t kFirstMinorWithPackedVertices = 5;
inline constexpr uint16_t kFirstMinorWithInstanceTransforms = 6;
inline constexpr uint16_t kFirstMinorWithDepthPrograms = 7;
inline constexpr uint16_t kFirstMinorWithPreshaderDivision = 8;

enum class Stage : uint8_t { Vertex = 0, Fragment = 1 };

enum class Target : uint8_t {
  GlslEs300 = 0,  // GLSL ES 3.00 source for OpenGL ES 3 / WebGL 2 (text)
  Spirv = 1,      // SPIR-V 1.0 module for Vulkan (little-endian words)
  Msl = 2,        // Metal Shading Language source (text)
};

const char* toString(Stage);
const char* toString(Target);

// TextureSrgb / TextureLinear / TextureNormal: a 2D texture and how its image is encoded (a normal
// map is linear data, RGB = tangent-space xyz * 0.5 + 0.5). Its default is the
// RGBA (as encoded) a missing image samples as; `offset` holds its sampler slot i (binding
// abi::kMaterialTextureBase + i), or kNoTextureSlot when the material never samples it.
enum class ParamType : uint8_t { Float, Vec2, Vec3, Vec4, Int, Bool, Color, TextureSrgb, TextureLinear, TextureNormal };
inline constexpr uint32_t kNoTextureSlot = 0xffffffffu;
inline bool isTexture(ParamType t) {
  return t == ParamType::TextureSrgb || t == ParamType::TextureLinear || t == ParamType::TextureNormal;
}
const char* toString(ParamType);
std::optional<ParamType> paramTypeFromString(std::string_view);

// One material parameter and where it lives in the std140 block "MaterialParams".
struct Param {
  std::string name;
  ParamType type = ParamType::Float;
  std::vector<double> defaultValue;  // component count of the type; colours stored linear
  std::optional<double> rangeMin;    // declared range `in [min, max]`, if any
  std::optional<double> rangeMax;
  uint32_t offset = 0;  // byte offset in the block
  uint32_t size = 0;    // byte size in the block
  bool operator==(const Param&) const = default;
};

struct MaterialInfo {
  std::string name;
  std::string shading;       // "lit" | "unlit"
  std::string blending;      // "opaque" | "masked" | "transparent" | "additive"
  bool doubleSided = false;  // false: the runtime culls back faces (counter-clockwise is front)
  std::vector<Param> params;
  uint32_t paramBlockSize = 0;  // std140 size of "MaterialParams" in bytes (0: no block)
  bool operator==(const MaterialInfo&) const = default;
};

struct Shader {
  Stage stage = Stage::Vertex;
  Target target = Target::GlslEs300;
  std::vector<uint8_t> code;  // text for GLSL/MSL, SPIR-V words as bytes
  bool operator==(const Shader&) const = default;
};

// One permutation. `key` is the stable variant key string (see permutations/variant_key.h).
struct Variant {
  std::string key;
  std::vector<Shader> shaders;
  bool operator==(const Variant&) const = default;
};

// How a package texture's texels are encoded.
enum class TexelFormat : uint8_t {
  R8Unorm = 0,  // 1 byte per texel: value / 255
};
const char* toString(TexelFormat);
inline uint32_t bytesPerTexel(TexelFormat) { return 1; }  // R8Unorm is the only format so far

// A texture the compiler generated for the shaders, not one the material declares: e.g. the
// specular table of the `lut` tier. Stored in section TEXS; its texels are a blob, deduplicated
// and compressed like shader code.
struct Texture {
  std::string name;  // the sampler the shaders declare, e.g. "facet_specularLut" (shader_abi.h)
  uint32_t width = 0;
  uint32_t height = 0;
  TexelFormat format = TexelFormat::R8Unorm;
  std::vector<uint8_t> texels;     // row-major from row 0 (t = 0): width × height × bytes per texel
  std::vector<uint32_t> variants;  // indices into Package::variants of the variants that sample it, increasing
  bool operator==(const Texture&) const = default;
};

// Where a Metal app binds one resource of the MSL shaders: the same slot in every variant
// (pinned from shader_abi.h by the compiler). A Buffer is a uniform block at [[buffer(index)]];
// a Texture is a combined sampler at [[texture(index)]] and [[sampler(index)]]. `set`/`binding`
// are its Vulkan descriptor, so an engine can map one to the other.
enum class MslResource : uint8_t { Buffer = 0, Texture = 1 };
const char* toString(MslResource);
struct MslBinding {
  std::string name;  // block type name ("FrameUniforms") or sampler name ("facet_environment")
  MslResource kind = MslResource::Buffer;
  uint32_t set = 0;
  uint32_t binding = 0;
  uint32_t index = 0;  // Metal argument table index
  bool operator==(const MslBinding&) const = default;
};
// Metal's argument tables: 31 buffers; 16 samplers on iOS (a Texture uses a texture and a sampler).
inline constexpr uint32_t kMslBufferSlots = 31;
inline constexpr uint32_t kMslSamplerSlots = 16;
// The Metal slots of a material's shaders, pinned from shader_abi.h: the frame and object blocks,
// the material's block when it has one, the frame samplers of lit materials (the irradiance cube
// only in a package whose variants read it: diffuse `cube`), and one sampler per texture parameter
// with a sampler slot, and in a package holding shadow receivers (.sh variants) the shadow's block
// and atlas. The same for every variant; what the compiler records.
std::vector<MslBinding> mslBindingsFor(const MaterialInfo& material, bool shadowReceivers = false,
                                       bool irradianceCube = false);
// Recorded slots against the material (part of semanticError): each names a block or sampler the
// material's shaders declare, with that resource's kind, Vulkan set and binding and pinned index,
// and every such resource has one. "" when they agree or none are recorded (before format 1.2).
std::string mslBindingsError(const MaterialInfo& material, const std::vector<MslBinding>& bindings,
                             bool shadowReceivers = false);

// The preshader (Unreal's term; format 1.3, section PRSH): shading inputs that depend only on
// parameters (f0, diffuse colour, clamped roughness, α), computed once on the CPU when an
// instance's parameters change and written into the uniform block as members after the
// parameters, instead of per pixel. A program is data: ops on kPreshaderRegisters vec4
// registers (all zero at the start) that read the parameter bytes and write the derived ones.
// The runtime interprets it without knowing what it computes (docs/package-format.md, "PRSH").
enum class PreshaderOpcode : uint8_t {
  LoadParam = 0,  // r[dst] = `count` floats at block byte `offset` (in the parameters); count 1 broadcasts
  Constant = 1,   // r[dst] = k
  Add = 2,        // r[dst] = r[a] + r[b], per component
  Sub = 3,        // r[dst] = r[a] - r[b]
  Mul = 4,        // r[dst] = r[a] * r[b]
  Clamp = 5,      // r[dst] = min(max(r[a], k[0]), k[1]); NaN becomes k[0]
  Swizzle = 6,    // r[dst][i] = r[a][(offset >> 2i) & 3]
  Store = 7,      // `count` floats of r[a] to block byte `offset` (after the parameters)
  Div = 8,        // r[dst] = r[a] / r[b] (format 1.8)
  Sqrt = 9,       // r[dst] = sqrt(r[a]) (format 1.8)
};
inline constexpr uint8_t kLastPreshaderOpcode = uint8_t(PreshaderOpcode::Sqrt);
const char* toString(PreshaderOpcode);
struct PreshaderOp {
  PreshaderOpcode code = PreshaderOpcode::Constant;
  uint8_t dst = 0, a = 0, b = 0;  // registers
  uint32_t offset = 0;
  uint32_t count = 0;
  std::array<float, 4> k{};
  bool operator==(const PreshaderOp&) const = default;
};
struct PreshaderProgram {
  std::vector<uint32_t> variants;  // indices into Package::variants, increasing; each in one program at most
  std::vector<PreshaderOp> ops;
  bool operator==(const PreshaderProgram&) const = default;
};
struct Preshader {
  // Bytes of "MaterialParams" with the derived members: paramBlockSize < blockSize, a multiple
  // of 16. Variants without a program declare and upload paramBlockSize bytes, as before 1.3.
  uint32_t blockSize = 0;
  std::vector<PreshaderProgram> programs;  // empty: no PRSH section
  bool operator==(const Preshader&) const = default;
};
inline constexpr uint32_t kPreshaderRegisters = 64;
inline constexpr size_t kMaxPreshaderOps = 256;
// Whether a program uses an op of format 1.8 (the writer stamps 1.8; an older minor with one is
// refused).
bool usesPreshaderDivision(std::span<const PreshaderOp> ops);
// What is wrong with a program run over a block of `blockSize` bytes whose first
// `paramBlockSize` are the parameters, or "": known opcodes, registers in range, 1..4 components,
// 4-byte aligned offsets, loads inside the parameters, stores after them and inside the block,
// finite constants, at most kMaxPreshaderOps ops. Nothing a program does can then reach memory
// outside the block or overwrite a parameter.
std::string preshaderError(std::span<const PreshaderOp> ops, uint32_t paramBlockSize, uint32_t blockSize);
// The package's preshader against its material: a block above the parameters, every program
// sound by preshaderError. "" when there is no preshader. Part of semanticError.
std::string preshaderSemanticError(const MaterialInfo& material, const Preshader& preshader);

struct Package {
  std::string compilerVersion;
  MaterialInfo material;
  std::vector<Variant> variants;
  std::vector<Texture> textures;        // written (as section TEXS) only when not empty
  std::vector<MslBinding> mslBindings;  // written (as section MSLB, format 1.2) only when not empty
  Preshader preshader;                  // written (as section PRSH, format 1.3) only with programs
  // The shaders read shader_abi.h's two vertex streams and decode positions and UVs from
  // ObjectUniforms (what matc builds since format 1.5): stamped 1.5, and read back from it.
  bool packedVertices = false;
  // The vertex shaders read their transform from the instance stream (shader_abi.h
  // InstanceTransform) instead of ObjectUniforms (what matc builds since format 1.6): stamped 1.6.
  bool instanceTransforms = false;
  bool operator==(const Package&) const = default;
};

// Same package and compiler version in, same bytes out.
std::vector<uint8_t> write(const Package& pkg);

// Sizes as stored, for `matc info`.
struct ShaderStats {
  uint64_t rawSize = 0;     // bytes of code
  uint64_t storedSize = 0;  // bytes in the file (compressed, shared if deduplicated)
};

struct ReadResult {
  std::optional<Package> package;  // set on success
  std::string error;               // set on failure: what is wrong, and where (byte offset)
  // Per variant, per shader (same order as Package::variants[i].shaders).
  std::vector<std::vector<ShaderStats>> stats;
  // Per texture (same order as Package::textures); a blob shared with a shader is charged there.
  std::vector<ShaderStats> textureStats;
  // Stored bytes of the blob no shader or texture uses itself: the compression dictionary
  // (format 1.1). The stats above plus this sum to the size of the blob data.
  uint64_t dictionaryStoredSize = 0;
  uint16_t formatMajor = 0, formatMinor = 0;  // as stamped in the file
};

// Validates every offset, size, count, version and the checksum before use. Never crashes,
// never allocates more than the input can justify, on any input.
ReadResult read(std::span<const uint8_t> bytes);

// Limits a package must respect (the compiler's own: ir::kMaxParams, their std140 vec4 slots).
inline constexpr size_t kMaxParams = 256;
inline constexpr uint32_t kMaxParamBlockBytes = 256 * 16;
inline constexpr size_t kMaxNameBytes = 128;

// A material or parameter name as the language writes it: letters, digits and _, not starting
// with a digit, at most kMaxNameBytes. Scenes name packages and parameters with the same rule.
bool isValidName(std::string_view name);

// Whether a variant key names a depth-only program of the shadow pass (`<tier>.depth`,
// permutations::VariantKey::depthOnly): such variants need format 1.7.
bool isDepthProgramKey(std::string_view key);

// What a decoded package means, checked for a package the app did not build (the runtime's
// loader calls it on every package): identifier names, known shading and blending, unique
// parameters and variants, valid variant keys, finite ordered ranges holding their defaults,
// sizes within the limits above, preshader programs that stay inside the block
// (preshaderSemanticError), and shader blobs of the kind their slot says (SPIR-V words,
// GLSL ES 3.00 text). "" when it is sound, else what is wrong. read() checks bytes only, so that
// tools can still open and describe a package whose meaning is wrong.
std::string semanticError(const Package& pkg);

// Reads a whole file; on I/O failure returns a ReadResult with the error set.
ReadResult readFile(const std::string& path);

// Writes atomically (AtomicFile: a fresh temporary file, then a rename), so a failed or
// interrupted write never leaves a partial file, and refuses a destination that is not a regular file.
bool writeFile(const std::string& path, std::span<const uint8_t> bytes, std::string* error);

struct OutputFile {
  std::string path;
  std::vector<uint8_t> bytes;
};
// Writes several files as one output: every file to its temporary file first, then the renames,
// so a failure before the renames (a folder that cannot be written, a full disk, a destination
// that is not a regular file) leaves every destination as it was. Only a rename failing part way
// (same folder, same file system: rare) can leave the earlier files replaced.
bool writeFiles(const std::vector<OutputFile>& files, std::string* error);

}  // namespace facet::package
