// The package loader for apps: a .matpkg opened from memory or a file, whose shader code is
// decompressed only when a variant is first asked for.
//
// open() checks everything but the blob contents up front (header, checksum, table of contents,
// every section, every declared size and count against the bytes that back it and against the
// limits in format.h), so a reader that opened can list materials, parameters and variants
// without further failure. A blob is decoded (zstd, content hash) on its first request and kept;
// a blob stored raw is returned as a view of the input, never copied. package::read() is this
// reader with every blob requested, so tools and apps share one parser.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/package/package.h"

namespace facet::package {

// The rows of the variant and texture tables as sections VARS and TEXS store them (code and
// texels by blob index); package.h's Shader, Variant and Texture hold the bytes instead
// (package/src/rows.h converts one into the other).

// One shader of a variant, before its code is decoded. `blob` indexes PackageReader::blobs();
// shaders with equal code share one blob (and one decoded copy).
struct ShaderInfo {
  Stage stage = Stage::Vertex;
  Target target = Target::GlslEs300;
  uint32_t blob = 0;
};

struct VariantInfo {
  std::string key;  // stable variant key, e.g. "high.dir1" (permutations/variant_key.h)
  std::vector<ShaderInfo> shaders;
};

// A generated texture (section TEXS) before its texels are decoded.
struct TextureInfo {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  TexelFormat format = TexelFormat::R8Unorm;
  uint32_t blob = 0;
  std::vector<uint32_t> variants;  // indices into variants(), increasing
};

struct BlobInfo {
  uint64_t rawSize = 0;     // bytes once decoded
  uint64_t storedSize = 0;  // bytes in the file
  bool compressed = false;  // false: stored raw, served as a view of the input
};

// package::semanticError in two parts, for a reader that has not decoded any code: the material
// and the variant table ("" when sound), and one shader's code for its slot's kind (SPIR-V words,
// GLSL ES 3.00 text): "" or what it is not, e.g. "is not SPIR-V (...)".
std::string semanticError(const MaterialInfo& material, const std::vector<VariantInfo>& variants,
                          const Preshader& preshader = {}, const std::vector<MslBinding>& mslBindings = {});
std::string shaderCodeError(Target target, std::span<const uint8_t> code);

class PackageReader {
 public:
  // Borrows `bytes`: they must stay alive and unchanged as long as the reader and every span it
  // returned. Nothing is decompressed here. nullopt with *error (what is wrong and at which
  // byte) on any damaged or hostile input.
  static std::optional<PackageReader> open(std::span<const uint8_t> bytes, std::string* error);
  // Reads the whole file into memory the reader owns, then open()s it.
  static std::optional<PackageReader> openFile(const std::string& path, std::string* error);

  PackageReader(PackageReader&&) noexcept;
  PackageReader& operator=(PackageReader&&) noexcept;
  ~PackageReader();

  uint16_t formatMajor() const;
  uint16_t formatMinor() const;
  const std::string& compilerVersion() const;
  // Name, shading, blending, and the parameters: types, defaults, ranges, and their offsets in
  // the std140 block "MaterialParams" of paramBlockSize bytes (the parameter block layout).
  const MaterialInfo& material() const;
  const Param* findParam(std::string_view name) const;
  const std::vector<VariantInfo>& variants() const;
  const VariantInfo* findVariant(std::string_view key) const;
  const std::vector<TextureInfo>& textures() const;
  const std::vector<BlobInfo>& blobs() const;
  // Where a Metal app binds each block and sampler of the MSL shaders, the same in every
  // variant (format 1.2; empty in older packages).
  const std::vector<MslBinding>& mslBindings() const;
  // The preshader (format 1.3; empty in older packages; its programs are checked against the
  // block by semanticError(), package::preshaderError), and the program of one variant (nullptr: the variant computes
  // its inputs per pixel from the parameter block alone).
  const Preshader& preshader() const;
  const PreshaderProgram* preshaderProgram(std::string_view key) const;

  // What a package means, for one the app did not build: package::semanticError's checks of the
  // metadata and variant table, without decoding any code. The code of each shader is checked
  // for its kind (shaderCodeError) when an app first asks for it.
  std::string semanticError() const;

  // The code of the (stage, target) shader of variant `key`: decoded on the first request and
  // kept for the reader's lifetime. nullopt with *error when the variant or shader does not
  // exist, or the blob does not decode (zstd frame, content hash). Thread-safe.
  std::optional<std::span<const uint8_t>> shader(std::string_view key, Stage stage, Target target,
                                                 std::string* error) const;
  // The texels of textures()[index], decoded like shader code.
  std::optional<std::span<const uint8_t>> texels(size_t index, std::string* error) const;
  // Any blob by index (tools that walk them all: package::read).
  std::optional<std::span<const uint8_t>> blob(uint32_t index, std::string* error) const;

  // Bytes zstd has written so far, package dictionaries included; a raw blob costs nothing.
  uint64_t bytesDecompressed() const;

 private:
  struct State;
  explicit PackageReader(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace facet::package
