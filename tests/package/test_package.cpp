// .matpkg writer and reader: round trip, determinism, deduplication, and rejection of every
// kind of damaged or hostile input. Byte positions used here are from docs/package-format.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <unistd.h>

#define XXH_INLINE_ALL
#include <xxhash.h>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"
#include "test_support.h"

namespace pkg = facet::package;

#ifdef __SANITIZE_ADDRESS__
// Turns "allocated far more than the input justifies" into a hard failure under ASan, rather
// than something overcommit lets pass. The reader's own cap on decoded code is 1 GiB.
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=1100"; }
#endif

namespace {

std::vector<uint8_t> textCode(const std::string& s) { return {s.begin(), s.end()}; }

std::vector<uint8_t> glslSource(const std::string& body) {
  std::string s = "#version 300 es\nprecision mediump float;\n";
  for (int i = 0; i < 40; ++i) s += "uniform vec4 u_light" + std::to_string(i) + "; // " + body + "\n";
  s += "void main() { " + body + " }\n";
  return textCode(s);
}

// Pseudo-random words: incompressible, so they exercise the raw codec.
std::vector<uint8_t> spirvWords(uint32_t seed, size_t words) {
  std::mt19937 rng(seed);
  std::vector<uint8_t> code;
  const uint32_t magic = 0x07230203;
  for (size_t i = 0; i < words; ++i) {
    uint32_t w = i == 0 ? magic : uint32_t(rng());
    for (int b = 0; b < 4; ++b) code.push_back(uint8_t(w >> (8 * b)));
  }
  return code;
}

pkg::Package samplePackage() {
  pkg::Package p;
  p.compilerVersion = "matc 0.1.0 (test)";
  p.material.name = "brick";
  // Unlit: a lit package is stamped 1.4 whatever else it holds (below), which would hide the
  // older minors' stamps these tests check.
  p.material.shading = "unlit";
  p.material.blending = "opaque";
  p.material.paramBlockSize = 64;
  p.material.params = {
      {"roughness", pkg::ParamType::Float, {0.5}, 0.089, 1.0, 0, 4},
      {"tint", pkg::ParamType::Color, {0.8, 0.2, 0.1, 1.0}, std::nullopt, std::nullopt, 16, 16},
      {"offset", pkg::ParamType::Vec3, {-0.0, 1e-300, 3.25}, -10.0, std::nullopt, 32, 12},
      {"tiles", pkg::ParamType::Int, {4}, std::nullopt, 16.0, 44, 4},
      {"wet", pkg::ParamType::Bool, {0}, std::nullopt, std::nullopt, 48, 4},
      {"uv", pkg::ParamType::Vec2, {1, 2}, std::nullopt, std::nullopt, 56, 8},
  };
  for (int i = 0; i < 3; ++i) {
    pkg::Variant v;
    v.key = "tier=mid;lights=" + std::to_string(i);
    v.shaders = {
        {pkg::Stage::Vertex, pkg::Target::GlslEs300, glslSource("gl_Position = vec4(0.0);")},
        {pkg::Stage::Fragment, pkg::Target::GlslEs300, glslSource("o = vec4(" + std::to_string(i) + ");")},
        {pkg::Stage::Vertex, pkg::Target::Spirv, spirvWords(100, 64)},
        {pkg::Stage::Fragment, pkg::Target::Spirv, spirvWords(200 + uint32_t(i), 96)},
        {pkg::Stage::Fragment, pkg::Target::Msl,
         textCode("#include <metal_stdlib>\nfragment half4 f() { return 1; }\n")},
    };
    p.variants.push_back(std::move(v));
  }
  // A generated table, sampled by variants 0 and 2 (TEXS section).
  pkg::Texture lut;
  lut.name = "facet_specularLut";
  lut.width = 16;
  lut.height = 8;
  for (uint32_t i = 0; i < lut.width * lut.height; ++i) lut.texels.push_back(uint8_t(i * 7 % 256));
  lut.variants = {0, 2};
  p.textures.push_back(std::move(lut));
  return p;
}

// The TEXS payload's first entry, as docs/package-format.md lays it out.
struct TexsEntry {
  size_t at;        // the entry's name length
  size_t width;     // u32 width; height, format, reserved, blob index and variant count follow
  size_t variants;  // the first variant index
};
TexsEntry firstTexture(const std::vector<uint8_t>& b);

uint64_t loadLE(const std::vector<uint8_t>& b, size_t at, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= uint64_t(b[at + size_t(i)]) << (8 * i);
  return v;
}

void storeLE(std::vector<uint8_t>& b, size_t at, uint64_t v, int n) {
  for (int i = 0; i < n; ++i) b[at + size_t(i)] = uint8_t(v >> (8 * i));
}

// Re-seals a hand-edited file, so the reader gets past the checksum to the check under test.
void resealChecksum(std::vector<uint8_t>& b) {
  storeLE(b, 24, 0, 8);
  storeLE(b, 24, XXH3_64bits(b.data(), b.size()), 8);
}

// File offset of a section's payload, found through the table of contents.
size_t sectionOffset(const std::vector<uint8_t>& b, const char* tag) {
  uint32_t count = uint32_t(loadLE(b, 12, 4));
  for (uint32_t i = 0; i < count; ++i) {
    size_t at = 32 + size_t(i) * 24;
    if (std::memcmp(&b[at], tag, 4) == 0) return size_t(loadLE(b, at + 8, 8));
  }
  ADD_FAILURE() << "no section " << tag;
  return 0;
}

size_t tocEntry(const std::vector<uint8_t>& b, const char* tag) {
  uint32_t count = uint32_t(loadLE(b, 12, 4));
  for (uint32_t i = 0; i < count; ++i) {
    size_t at = 32 + size_t(i) * 24;
    if (std::memcmp(&b[at], tag, 4) == 0) return at;
  }
  ADD_FAILURE() << "no section " << tag;
  return 0;
}

TexsEntry firstTexture(const std::vector<uint8_t>& b) {
  size_t at = sectionOffset(b, "TEXS") + 4;
  size_t width = at + 4 + loadLE(b, at, 4);
  return {at, width, width + 20};
}

// Writes `p`, expects the header's minor to be `minor` and the file to read back as `p`.
std::vector<uint8_t> expectStampedAndRoundTrips(const pkg::Package& p, uint64_t minor) {
  std::vector<uint8_t> bytes = pkg::write(p);
  EXPECT_EQ(loadLE(bytes, 10, 2), minor);
  pkg::ReadResult r = pkg::read(bytes);
  EXPECT_TRUE(r.package.has_value()) << r.error;
  if (r.package) {
    EXPECT_EQ(*r.package, p);
  }
  EXPECT_EQ(r.formatMinor, minor);
  return bytes;
}

void expectRejected(const std::vector<uint8_t>& bytes, const std::string& expectedPart) {
  pkg::ReadResult r = pkg::read(bytes);
  EXPECT_FALSE(r.package.has_value());
  EXPECT_NE(r.error.find(expectedPart), std::string::npos) << "error was: " << r.error;
}

// `good` with `edit` applied and its checksum made valid again, so the structural checks are
// what must reject it.
template <typename Edit>
void expectEditRejected(const std::vector<uint8_t>& good, Edit edit, const std::string& expectedPart) {
  std::vector<uint8_t> b = good;
  edit(b);
  resealChecksum(b);
  expectRejected(b, expectedPart);
}

std::filesystem::path scratchDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("facet_test_package_" + std::to_string(getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(Package, RoundTripPreservesEverything) {
  pkg::Package p = samplePackage();
  pkg::ReadResult r = pkg::read(pkg::write(p));
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_TRUE(r.error.empty());
  EXPECT_EQ(*r.package, p);
  EXPECT_TRUE(std::signbit(r.package->material.params[2].defaultValue[0]));  // -0.0 survives

  ASSERT_EQ(r.stats.size(), p.variants.size());
  for (size_t v = 0; v < p.variants.size(); ++v) {
    ASSERT_EQ(r.stats[v].size(), p.variants[v].shaders.size());
    for (size_t s = 0; s < p.variants[v].shaders.size(); ++s)
      EXPECT_EQ(r.stats[v][s].rawSize, p.variants[v].shaders[s].code.size());
  }
}

TEST(Package, EmptyPackageRoundTrips) {
  pkg::Package p;
  pkg::ReadResult r = pkg::read(pkg::write(p));
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
}

TEST(Package, OutputIsDeterministic) {
  pkg::Package p = samplePackage();
  pkg::Package copy = p;
  std::vector<uint8_t> a = pkg::write(p);
  std::vector<uint8_t> b = pkg::write(copy);
  EXPECT_EQ(a, b);
  EXPECT_EQ(pkg::write(*pkg::read(a).package), a);  // a read package writes back identically
}

TEST(Package, IdenticalShadersAreStoredOnce) {
  pkg::Package p = samplePackage();
  std::vector<uint8_t> before = pkg::write(p);

  pkg::Variant duplicate = p.variants[0];
  duplicate.key = "tier=mid;lights=0;copy";
  size_t codeSize = 0;
  for (const pkg::Shader& s : duplicate.shaders) codeSize += s.code.size();
  p.variants.push_back(duplicate);
  std::vector<uint8_t> after = pkg::write(p);

  // Only the key and the 8-byte shader references are added, not the code.
  EXPECT_LT(after.size() - before.size(), duplicate.key.size() + 8 + 5 * 8 + 8);
  EXPECT_LT(after.size() - before.size(), codeSize);

  pkg::ReadResult r = pkg::read(after);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  for (const pkg::ShaderStats& s : r.stats.back()) {
    EXPECT_GT(s.rawSize, 0u);
    EXPECT_EQ(s.storedSize, 0u);  // shared: charged to variant 0
  }
  for (const pkg::ShaderStats& s : r.stats[0]) EXPECT_GT(s.storedSize, 0u);
}

TEST(Package, TextIsCompressedAndRandomBytesAreStoredRaw) {
  pkg::Package p = samplePackage();
  pkg::ReadResult r = pkg::read(pkg::write(p));
  ASSERT_TRUE(r.package.has_value()) << r.error;
  const pkg::ShaderStats& glsl = r.stats[0][0];
  EXPECT_LT(glsl.storedSize * 4, glsl.rawSize);
  // Variant 1's random SPIR-V: not the dictionary's representative of its kind (variant 0's is).
  const pkg::ShaderStats& spirv = r.stats[1][3];
  EXPECT_EQ(spirv.storedSize, spirv.rawSize);
}

TEST(Package, TruncatedPackageIsRejected) {
  std::vector<uint8_t> bytes = pkg::write(samplePackage());
  for (size_t n = 0; n < bytes.size(); ++n) {
    pkg::ReadResult r = pkg::read(std::span(bytes.data(), n));
    ASSERT_FALSE(r.package.has_value()) << "accepted " << n << " bytes";
    ASSERT_FALSE(r.error.empty()) << "no error for " << n << " bytes";
  }
  expectRejected({bytes.begin(), bytes.begin() + 100}, "package is truncated: the header declares " +
                                                           std::to_string(bytes.size()) +
                                                           " bytes but the file has 100 bytes");
}

TEST(Package, FlippedByteIsRejectedWithChecksumError) {
  std::vector<uint8_t> bytes = pkg::write(samplePackage());
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::vector<uint8_t> damaged = bytes;
    damaged[i] ^= 0x10;
    pkg::ReadResult r = pkg::read(damaged);
    ASSERT_FALSE(r.package.has_value()) << "accepted a flip at byte " << i;
    ASSERT_FALSE(r.error.empty());
    // Magic, version and size are reported as such; everything else by the checksum.
    if (i >= 24) {
      ASSERT_EQ(r.error.rfind("checksum mismatch: file is corrupt", 0), 0u) << r.error;
    }
  }
}

// Format versions (docs/package-format.md, "Format version"): crafted headers, checksum resealed.
TEST(Package, NewerMinorIsRefusedNamingBothVersionsAndTheRebuildCommand) {
  std::vector<uint8_t> bytes = pkg::write(samplePackage());
  storeLE(bytes, 10, pkg::kFormatMinor + 1, 2);
  resealChecksum(bytes);
  pkg::ReadResult r = pkg::read(bytes);
  EXPECT_FALSE(r.package.has_value());
  const std::string ours = std::to_string(pkg::kFormatMajor) + "." + std::to_string(pkg::kFormatMinor);
  const std::string theirs = std::to_string(pkg::kFormatMajor) + "." + std::to_string(pkg::kFormatMinor + 1);
  EXPECT_EQ(r.error, "package format " + theirs + " is not supported: this reader reads formats " +
                         std::to_string(pkg::kFormatMajor) + ".0 to " + ours +
                         " (the package was built by a newer compiler); rebuild it with this release's compiler: "
                         "matc compile MATERIAL.mat -o PACKAGE.matpkg");
}

// A depth-only program of the shadow pass (`<tier>.depth`) stamps 1.7; a reader finding one in an
// older minor refuses the file (no writer of that version made it), naming the variant.
TEST(Package, DepthProgramsAreStampedOneSevenAndRefusedInOlderMinors) {
  pkg::Package p = samplePackage();
  std::vector<uint8_t> plain = pkg::write(p);
  EXPECT_LT(loadLE(plain, 10, 2), pkg::kFirstMinorWithDepthPrograms);
  p.variants[1].key = "mid.depth";
  std::vector<uint8_t> bytes = pkg::write(p);
  EXPECT_EQ(loadLE(bytes, 10, 2), pkg::kFirstMinorWithDepthPrograms);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package) << r.error;
  EXPECT_EQ(r.package->variants[1].key, "mid.depth");
  storeLE(bytes, 10, pkg::kFirstMinorWithDepthPrograms - 1, 2);
  resealChecksum(bytes);
  r = pkg::read(bytes);
  EXPECT_FALSE(r.package);
  EXPECT_EQ(r.error,
            "package format 1.6 has variant 'mid.depth', a depth-only program, which only format 1.7 and "
            "later have");
}

// A preshader program with a div or sqrt op stamps 1.8, so an older runtime refuses the file by
// its version; a reader finding one in an older minor refuses the file (no writer of that version
// made it).
TEST(Package, PreshaderDivisionIsStampedOneEightAndRefusedInOlderMinors) {
  pkg::Package p = samplePackage();
  p.preshader.blockSize = 96;
  pkg::PreshaderProgram program;
  program.variants = {0};
  program.ops = {{pkg::PreshaderOpcode::Constant, 1, 0, 0, 0, 0, {1.0f, 2.0f, 3.0f, 4.0f}},
                 {pkg::PreshaderOpcode::Mul, 2, 1, 1, 0, 0, {}},
                 {pkg::PreshaderOpcode::Store, 0, 2, 0, 64, 4, {}}};
  p.preshader.programs = {program};
  EXPECT_LT(loadLE(pkg::write(p), 10, 2), pkg::kFirstMinorWithPreshaderDivision);
  for (pkg::PreshaderOpcode code : {pkg::PreshaderOpcode::Div, pkg::PreshaderOpcode::Sqrt}) {
    p.preshader.programs[0].ops[1].code = code;
    std::vector<uint8_t> bytes = pkg::write(p);
    EXPECT_EQ(loadLE(bytes, 10, 2), pkg::kFirstMinorWithPreshaderDivision);
    pkg::ReadResult r = pkg::read(bytes);
    ASSERT_TRUE(r.package) << r.error;
    EXPECT_EQ(r.package->preshader, p.preshader);
    storeLE(bytes, 10, pkg::kFirstMinorWithPreshaderDivision - 1, 2);
    resealChecksum(bytes);
    r = pkg::read(bytes);
    EXPECT_FALSE(r.package);
    EXPECT_EQ(r.error,
              "package format 1.7 has a preshader program with a div or sqrt op, which only format 1.8 and later have");
  }
}

// The shadow pass draws only materials that cast: a transparent or additive one with a depth-only
// program is a package no compiler wrote.
TEST(Package, ADepthProgramOfAMaterialThatCastsNoShadowIsRefused) {
  pkg::Package p = samplePackage();
  p.variants[0].key = "mid.dir0";
  p.variants[1].key = "mid.depth";
  p.variants[2].key = "low.dir0";
  p.material.params.clear();  // sample ranges and layout are not what is under test
  p.material.paramBlockSize = 0;
  EXPECT_EQ(pkg::semanticError(p), "");
  for (const char* blending : {"transparent", "additive"}) {
    p.material.blending = blending;
    EXPECT_EQ(pkg::semanticError(p), "variant 'mid.depth' is a depth-only program, but a " + std::string(blending) +
                                         " material casts no shadow (only opaque and masked ones do)");
  }
  p.material.blending = "masked";
  EXPECT_EQ(pkg::semanticError(p), "");
}

TEST(Package, OtherMajorVersionsAreRefusedAndZeroIsInvalid) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  expectEditRejected(
      good, [](auto& b) { storeLE(b, 8, pkg::kFormatMajor + 1, 2); },
      "package format " + std::to_string(pkg::kFormatMajor + 1) + ".1 is not supported");
  expectEditRejected(
      good, [](auto& b) { storeLE(b, 8, pkg::kFormatMajor + 1, 2); }, "built by a newer compiler");
  expectEditRejected(
      good, [](auto& b) { storeLE(b, 8, 0, 2); }, "package format version 0.1 at byte 8 is not valid");
}

// A package that uses nothing newer than 1.0 is stamped 1.0, so readers from before 1.1 load it;
// this reader loads it too (an older minor of its own major).
TEST(Package, PackageWithoutNewerFeaturesIsStampedOneZeroAndLoads) {
  pkg::Package p = samplePackage();
  p.variants.resize(1);
  p.variants[0].shaders.resize(1);
  p.textures.clear();
  std::vector<uint8_t> bytes = pkg::write(p);
  EXPECT_EQ(loadLE(bytes, 8, 2), 1u);
  EXPECT_EQ(loadLE(bytes, 10, 2), 0u);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  EXPECT_EQ(r.formatMinor, 0u);
}

// The byte-for-byte example of docs/package-format.md, as the 1.0 writer produced it.
TEST(Package, FormatOneZeroPackageFromTheFormatDocumentLoads) {
  const std::vector<uint8_t> bytes = {
      0x89, 0x46, 0x50, 0x4b, 0x47, 0x0d, 0x0a, 0x1a, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x56, 0x01, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x05, 0xae, 0xc1, 0x91, 0xba, 0x48, 0xca, 0x56, 0x4d, 0x45, 0x54, 0x41, 0x00, 0x00,
      0x00, 0x00, 0x80, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x6b, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x56,
      0x41, 0x52, 0x53, 0x00, 0x00, 0x00, 0x00, 0xf0, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x24, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x42, 0x54, 0x41, 0x42, 0x00, 0x00, 0x00, 0x00, 0x18, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x2c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x42, 0x44, 0x41, 0x54, 0x00, 0x00, 0x00, 0x00, 0x48, 0x01,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x0e, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x0a, 0x00, 0x00, 0x00, 0x6d,
      0x61, 0x74, 0x63, 0x20, 0x30, 0x2e, 0x31, 0x2e, 0x30, 0x09, 0x00, 0x00, 0x00, 0x75, 0x6e, 0x6c, 0x69, 0x74, 0x5f,
      0x72, 0x65, 0x64, 0x05, 0x00, 0x00, 0x00, 0x75, 0x6e, 0x6c, 0x69, 0x74, 0x06, 0x00, 0x00, 0x00, 0x6f, 0x70, 0x61,
      0x71, 0x75, 0x65, 0x10, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x74, 0x69, 0x6e,
      0x74, 0x06, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00,
      0x00, 0x74, 0x69, 0x65, 0x72, 0x3d, 0x6c, 0x6f, 0x77, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x31,
      0x68, 0x4b, 0xcb, 0x6d, 0x72, 0x64, 0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x0e, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x0e, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x76, 0x6f, 0x69, 0x64, 0x20, 0x6d, 0x61, 0x69, 0x6e, 0x28, 0x29, 0x7b, 0x7d, 0x0a};
  ASSERT_EQ(bytes.size(), 342u);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(r.formatMinor, 0u);
  EXPECT_EQ(r.package->material.name, "unlit_red");
  ASSERT_EQ(r.package->variants.size(), 1u);
  EXPECT_EQ(textCode("void main(){}\n"), r.package->variants[0].shaders[1].code);
  // Written again by this writer: the same bytes (nothing in it needs 1.1).
  EXPECT_EQ(pkg::write(*r.package), bytes);
}

// Format 1.1: shader blobs compressed against one dictionary blob; each decodes with only it.
TEST(Package, ShaderBlobsAreCompressedAgainstOneDictionaryBlob) {
  pkg::Package p = samplePackage();
  std::vector<uint8_t> bytes = expectStampedAndRoundTrips(p, 1);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_GT(r.dictionaryStoredSize, 0u);
  const size_t table = sectionOffset(bytes, "BTAB");
  const uint32_t count = uint32_t(loadLE(bytes, table, 4));
  size_t dictionaryCoded = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const size_t entry = table + 4 + 40 * i;
    if (loadLE(bytes, entry + 32, 4) != 2) continue;
    ++dictionaryCoded;
    EXPECT_EQ(loadLE(bytes, entry + 36, 4), count - 1) << "blob " << i;  // the dictionary comes last
  }
  EXPECT_GE(dictionaryCoded, 3u);
}

TEST(Package, HostileDictionaryReferencesAreRejected) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  const size_t table = sectionOffset(good, "BTAB");
  const uint32_t count = uint32_t(loadLE(good, table, 4));
  size_t coded = 0;  // the first dictionary-coded blob's table entry
  for (uint32_t i = 0; i < count && !coded; ++i)
    if (loadLE(good, table + 4 + 40 * i + 32, 4) == 2) coded = table + 4 + 40 * i;
  ASSERT_NE(coded, 0u);
  expectEditRejected(
      good, [&](auto& b) { storeLE(b, coded + 36, count, 4); }, "names dictionary blob");
  expectEditRejected(
      good, [&](auto& b) { storeLE(b, coded + 36, uint32_t((coded - table - 4) / 40), 4); },
      "itself compressed against a dictionary");
  expectEditRejected(
      good, [&](auto& b) { storeLE(b, 10, 0, 2); }, "which format 1.0 does not have");
  expectEditRejected(
      good, [&](auto& b) { storeLE(b, coded + 32, 1, 4); }, "names a dictionary but its codec does not use one");
  expectEditRejected(
      good, [&](auto& b) { storeLE(b, coded + 32, 3, 4); }, "unknown codec 3");
}

TEST(Package, NonPackageIsRejectedByMagic) {
  expectRejected(textCode("#version 300 es\nvoid main() {}\n"), "not a Facet package");
  expectRejected({}, "package is truncated");
}

// Each case has a valid checksum, so the structural check is what must catch it. Under ASan an
// allocation sized from one of these numbers would abort the test.
TEST(Package, HostileCountsDoNotAllocate) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  auto hostile = [&](auto edit, const std::string& expectedPart) { expectEditRejected(good, edit, expectedPart); };

  hostile([](auto& b) { storeLE(b, 12, 0xFFFFFFFF, 4); }, "sections");
  hostile(
      [](auto& b) {
        b.resize(100);
        storeLE(b, 16, 100, 8);
      },
      "package is truncated: table of contents ends at byte 152 but the file has 100 bytes");  // 32 + 5 × 24
  hostile([](auto& b) { storeLE(b, tocEntry(b, "BDAT") + 16, ~uint64_t(0) - 4, 8); }, "past the end");
  hostile([](auto& b) { storeLE(b, tocEntry(b, "BDAT") + 8, ~uint64_t(0) - 4, 8); }, "past the end");
  hostile([](auto& b) { storeLE(b, tocEntry(b, "META") + 8, 40, 8); }, "inside the header");
  hostile([](auto& b) { storeLE(b, tocEntry(b, "VARS") + 8, sectionOffset(b, "META"), 8); }, "overlaps");
  hostile([](auto& b) { std::memcpy(&b[tocEntry(b, "VARS")], "META", 4); }, "exactly one");

  // Counts and lengths at the start of each section.
  hostile([](auto& b) { storeLE(b, sectionOffset(b, "BTAB"), 0xFFFFFFFF, 4); }, "blob count 4294967295");
  hostile([](auto& b) { storeLE(b, sectionOffset(b, "VARS"), 0xFFFFFFFF, 4); }, "variant count 4294967295");
  hostile([](auto& b) { storeLE(b, sectionOffset(b, "META"), 0xFFFFFFF0, 4); }, "compiler version");
  hostile([](auto& b) { storeLE(b, sectionOffset(b, "VARS") + 4, 0x7FFFFFFF, 4); }, "variant key");

  // Blob 0's table entry: hash, offset, stored size, raw size, codec, reserved.
  const size_t blob0 = sectionOffset(good, "BTAB") + 4;
  hostile([&](auto& b) { storeLE(b, blob0 + 24, uint64_t(1) << 40, 8); }, "raw size");
  hostile([&](auto& b) { storeLE(b, blob0 + 16, uint64_t(1) << 40, 8); }, "stored bytes");
  hostile([&](auto& b) { storeLE(b, blob0 + 8, 8, 8); }, "starts at data offset 8");
  hostile([&](auto& b) { storeLE(b, blob0 + 32, 7, 4); }, "unknown codec 7");
  hostile([&](auto& b) { b[blob0] ^= 1; }, "content hash mismatch");
  // A zstd frame whose header disagrees with the table's raw size is refused before allocating.
  hostile([&](auto& b) { storeLE(b, blob0 + 24, loadLE(b, blob0 + 24, 8) + 1, 8); }, "zstd frame of");

  // First shader of the first variant: stage, target, reserved, blob index.
  const size_t vars = sectionOffset(good, "VARS");
  const size_t shader0 = vars + 4 + 4 + loadLE(good, vars + 4, 4) + 4;
  hostile([&](auto& b) { b[shader0] = 9; }, "unknown stage 9");
  hostile([&](auto& b) { b[shader0 + 1] = 9; }, "unknown target 9");
  hostile([&](auto& b) { storeLE(b, shader0 + 4, 0xFFFFFFFF, 4); }, "refers to blob 4294967295");
}

// Damage anywhere past the header, re-sealed so it reaches the structural checks: whatever the
// reader makes of it, it must answer with a package or an error, and not crash (ASan checks).
TEST(Package, RandomDamageWithValidChecksumNeverCrashes) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  std::mt19937 rng(1234);
  for (int round = 0; round < 3000; ++round) {
    std::vector<uint8_t> b = good;
    int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      size_t at = 32 + rng() % (b.size() - 32);
      b[at] = (rng() % 2) ? uint8_t(rng()) : uint8_t(b[at] ^ 0xFF);
    }
    resealChecksum(b);
    pkg::ReadResult r = pkg::read(b);
    ASSERT_NE(r.package.has_value(), !r.error.empty()) << r.error;
  }
}

TEST(Package, BadParameterIsRejected) {
  pkg::Package p = samplePackage();
  p.material.params[2].defaultValue.pop_back();  // vec3 with two components
  expectRejected(pkg::write(p), "parameter 'offset' at byte");

  // The type byte follows the first parameter's name (see docs/package-format.md, META).
  std::vector<uint8_t> b = pkg::write(samplePackage());
  size_t at = sectionOffset(b, "META");
  for (int i = 0; i < 4; ++i) at += 4 + loadLE(b, at, 4);  // four strings
  at += 4;                                                 // block size
  std::vector<uint8_t> flag = b;                           // the double-sided flag: 0 or 1
  flag[at] = 2;
  resealChecksum(flag);
  expectRejected(flag, "material flag 'double sided' is 2 (0 or 1)");
  at += 1 + 4;                 // flag, parameter count
  at += 4 + loadLE(b, at, 4);  // parameter name
  b[at] = 200;
  resealChecksum(b);
  expectRejected(b, "has unknown type 200");
}

TEST(Package, NamesMatchTheFormatDocument) {
  EXPECT_STREQ(pkg::toString(pkg::Stage::Vertex), "vertex");
  EXPECT_STREQ(pkg::toString(pkg::Stage::Fragment), "fragment");
  EXPECT_STREQ(pkg::toString(pkg::Target::GlslEs300), "glsl_es_300");
  EXPECT_STREQ(pkg::toString(pkg::Target::Spirv), "spirv");
  EXPECT_STREQ(pkg::toString(pkg::Target::Msl), "msl");
  for (const char* name : {"float", "vec2", "vec3", "vec4", "int", "bool", "color"}) {
    std::optional<pkg::ParamType> t = pkg::paramTypeFromString(name);
    ASSERT_TRUE(t.has_value()) << name;
    EXPECT_STREQ(pkg::toString(*t), name);
  }
  EXPECT_FALSE(pkg::paramTypeFromString("mat4").has_value());
  EXPECT_FALSE(pkg::paramTypeFromString("").has_value());
}

TEST(Package, WriteFileThenReadFileRoundTrips) {
  auto dir = scratchDir("roundtrip");
  const std::string path = (dir / "brick.matpkg").string();
  pkg::Package p = samplePackage();
  std::string error;
  ASSERT_TRUE(pkg::writeFile(path, pkg::write(p), &error)) << error;
  p.material.name = "brick2";  // overwriting an existing package replaces it
  ASSERT_TRUE(pkg::writeFile(path, pkg::write(p), &error)) << error;
  pkg::ReadResult r = pkg::readFile(path);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temp left
  std::filesystem::remove_all(dir);
}

TEST(Package, WriteFileIsAtomic) {
  auto dir = scratchDir("atomic");
  const std::vector<uint8_t> bytes = pkg::write(samplePackage());
  std::string error;

  // Directory does not exist: nothing can be created.
  const auto missing = dir / "missing" / "brick.matpkg";
  EXPECT_FALSE(pkg::writeFile(missing.string(), bytes, &error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(std::filesystem::exists(missing));

  // The temporary file is written but the rename fails (the target is a directory): the
  // temporary file must be cleaned up and the target left as it was.
  const auto target = dir / "occupied.matpkg";
  std::filesystem::create_directory(target);
  std::filesystem::create_directory(target / "child");
  error.clear();
  EXPECT_FALSE(pkg::writeFile(target.string(), bytes, &error));
  EXPECT_NE(error.find("cannot write '" + target.string() + "'"), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::is_directory(target));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
  std::filesystem::remove_all(dir);
}

TEST(Package, ReadFileReportsMissingFile) {
  pkg::ReadResult r = pkg::readFile("/nonexistent/facet/brick.matpkg");
  EXPECT_FALSE(r.package.has_value());
  EXPECT_NE(r.error.find("/nonexistent/facet/brick.matpkg"), std::string::npos) << r.error;
}

TEST(Package, TexturesRoundTripAndShareBlobsWithEqualContent) {
  pkg::Package p = samplePackage();
  pkg::Texture copy = p.textures[0];
  copy.name = "second_table";
  copy.variants = {1};
  p.textures.push_back(copy);
  std::vector<uint8_t> bytes = pkg::write(p);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  ASSERT_EQ(r.textureStats.size(), 2u);
  EXPECT_EQ(r.textureStats[0].rawSize, 128u);
  EXPECT_GT(r.textureStats[0].storedSize, 0u);
  EXPECT_EQ(r.textureStats[1].storedSize, 0u);  // same texels: one blob, charged to the first
  EXPECT_EQ(pkg::write(*r.package), bytes);
}

// TEXS is written only when there are textures: a package without them keeps the four sections
// (and the bytes) of the format before TEXS existed.
TEST(Package, TexturesAreAnOptionalFifthSection) {
  pkg::Package p = samplePackage();
  std::vector<uint8_t> with = pkg::write(p);
  EXPECT_EQ(loadLE(with, 12, 4), 5u);
  EXPECT_EQ(std::memcmp(&with[32 + 2 * 24], "TEXS", 4), 0);  // META, VARS, TEXS, BTAB, BDAT
  p.textures.clear();
  std::vector<uint8_t> without = pkg::write(p);
  EXPECT_EQ(loadLE(without, 12, 4), 4u);
  for (uint32_t i = 0; i < 4; ++i) EXPECT_NE(std::memcmp(&without[32 + i * 24], "TEXS", 4), 0);
  pkg::ReadResult r = pkg::read(without);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_TRUE(r.package->textures.empty());
}

// docs/package-format.md, "Section TEXS": the example's bytes, pinned.
TEST(Package, TexsSectionMatchesTheDocumentedExample) {
  pkg::Package p;
  p.compilerVersion = "matc 0.1.0";
  p.material = {"m", "lit", "opaque", false, {}, 0};
  p.variants = {{"low.dir0", {}}, {"low.dir1", {}}};
  p.textures = {{"lut", 4, 2, pkg::TexelFormat::R8Unorm, {0, 64, 128, 255, 0, 16, 32, 64}, {1}}};
  std::vector<uint8_t> b = pkg::write(p);
  const size_t at = sectionOffset(b, "TEXS");
  const uint8_t expected[] = {
      0x01, 0x00, 0x00, 0x00,                          // 1 texture
      0x03, 0x00, 0x00, 0x00, 'l',  'u',  't',         // name "lut"
      0x04, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,  // 4 x 2
      0x00, 0x00, 0x00, 0x00,                          // r8_unorm, reserved
      0x00, 0x00, 0x00, 0x00,                          // blob 0
      0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00,  // 1 variant: index 1 ("low.dir1")
  };
  ASSERT_EQ(loadLE(b, tocEntry(b, "TEXS") + 16, 8), sizeof expected);
  EXPECT_EQ(std::vector<uint8_t>(b.begin() + long(at), b.begin() + long(at + sizeof expected)),
            std::vector<uint8_t>(std::begin(expected), std::end(expected)));
  pkg::ReadResult r = pkg::read(b);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
}

// Every field of a TEXS entry is checked; each case has a valid checksum.
TEST(Package, HostileTextureFieldsAreRejected) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  auto hostile = [&](auto edit, const std::string& expectedPart) { expectEditRejected(good, edit, expectedPart); };
  const TexsEntry t = firstTexture(good);
  const size_t texs = sectionOffset(good, "TEXS");
  hostile([&](auto& b) { storeLE(b, texs, 0xFFFFFFFF, 4); }, "texture count 4294967295");
  hostile([&](auto& b) { storeLE(b, texs, 0, 4); }, "unexpected trailing bytes");
  hostile([&](auto& b) { storeLE(b, t.at, 0x7FFFFFFF, 4); }, "texture name at byte");
  hostile([&](auto& b) { b[t.at + 4] = '9'; }, "not an identifier");
  hostile([&](auto& b) { b[t.at + 5] = ' '; }, "not an identifier");
  hostile([&](auto& b) { storeLE(b, t.width, 0, 4); }, "is 0x8; each side must be 1..16384");
  hostile([&](auto& b) { storeLE(b, t.width + 4, 16385, 4); }, "is 16x16385");
  hostile([&](auto& b) { storeLE(b, t.width, 8, 4); }, "needs 64 bytes of texels but blob");
  hostile([&](auto& b) { b[t.width + 8] = 1; }, "unknown texel format 1");
  hostile([&](auto& b) { b[t.width + 9] = 1; }, "reserved bits set");
  hostile([&](auto& b) { b[t.width + 11] = 0x80; }, "reserved bits set");
  hostile([&](auto& b) { storeLE(b, t.width + 12, 99, 4); }, "refers to blob 99");
  hostile([&](auto& b) { storeLE(b, t.width + 12, 0, 4); }, "needs 128 bytes of texels but blob 0 holds");
  hostile([&](auto& b) { storeLE(b, t.width + 16, 0x40000000, 4); }, "variant index count 1073741824");
  hostile([&](auto& b) { storeLE(b, t.variants, 3, 4); }, "lists variant 3 but the package has 3 variants");
  hostile([&](auto& b) { storeLE(b, t.variants + 4, 0, 4); }, "lists variant 0 after 0 (indices must increase)");
}

TEST(Package, TwoTextureSectionsAreRejected) {
  // Two TEXS entries in the table of contents, both valid on their own: the second is appended
  // as a copy of the first's bytes after the last section.
  std::vector<uint8_t> b = pkg::write(samplePackage());
  const size_t entry = tocEntry(b, "TEXS");
  const uint64_t offset = loadLE(b, entry + 8, 8), size = loadLE(b, entry + 16, 8);
  std::vector<uint8_t> payload(b.begin() + long(offset), b.begin() + long(offset + size));
  // Rebuild: header + 6 TOC entries (the old 5 shifted by 24 bytes) + sections + the copy.
  uint32_t count = uint32_t(loadLE(b, 12, 4));
  std::vector<uint8_t> out(b.begin(), b.begin() + 32);
  for (uint32_t i = 0; i < count; ++i) {
    std::vector<uint8_t> e(b.begin() + long(32 + i * 24), b.begin() + long(32 + (i + 1) * 24));
    storeLE(e, 8, loadLE(e, 8, 8) + 24, 8);
    out.insert(out.end(), e.begin(), e.end());
  }
  // The copy starts at the next 8-byte boundary, as sections do.
  const uint64_t copyAt = (b.size() + 24 + 7) / 8 * 8;
  std::vector<uint8_t> extra(b.begin() + long(entry), b.begin() + long(entry + 24));
  storeLE(extra, 8, copyAt, 8);
  out.insert(out.end(), extra.begin(), extra.end());
  out.insert(out.end(), b.begin() + long(32 + count * 24), b.end());
  out.resize(copyAt, 0);
  out.insert(out.end(), payload.begin(), payload.end());
  storeLE(out, 12, count + 1, 4);
  storeLE(out, 16, out.size(), 8);
  resealChecksum(out);
  expectRejected(out, "more than one 'TEXS' section");
}

TEST(Package, TextureWhoseTexelsDoNotFitItsSizeIsRejected) {
  pkg::Package p = samplePackage();
  p.textures[0].texels.pop_back();
  expectRejected(pkg::write(p), "needs 128 bytes of texels but blob");
  p = samplePackage();
  p.textures[0].variants = {2, 0};
  expectRejected(pkg::write(p), "indices must increase");
}

// The package fuzzer's seeds (real packages) and every finding it ever made
// (tests/fuzz/package_corpus/, package_regressions/): each is read without crashing, a rejection
// says why, and what reads writes and reads back to the same package (fuzz_package's invariants).
TEST(Package, FuzzSeedsAndRegressionsAreReadWithoutCrashing) {
  size_t seeds = 0;
  for (const char* folder : {"package_corpus", "package_regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(facet::test::sourceDir()) / "tests/fuzz" / folder;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() == ".md") continue;
      SCOPED_TRACE(entry.path().string());
      std::ifstream in(entry.path(), std::ios::binary);
      std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      pkg::ReadResult r = pkg::read(bytes);
      if (std::string(folder) == "package_corpus") {
        ++seeds;
        ASSERT_TRUE(r.package.has_value()) << r.error;
      }
      if (!r.package) {
        EXPECT_FALSE(r.error.empty());
        continue;
      }
      const std::vector<uint8_t> written = pkg::write(*r.package);
      pkg::ReadResult again = pkg::read(written);
      ASSERT_TRUE(again.package.has_value()) << again.error;
      EXPECT_EQ(pkg::write(*again.package), written);
    }
  }
  EXPECT_EQ(seeds, 6u);
}

// Format 1.4: a lit material's shaders sample the environment as a cube map, so a lit package is
// stamped 1.4 and a reader (or runtime) of 1.3, which binds an octahedral map there, refuses it.
// This reader still reads older lit packages (the runtime refuses to draw them:
// PreshaderRender.AnOlderLitPackageIsRefusedWithARebuildMessage).
TEST(Package, LitPackagesAreStampedOneFour) {
  pkg::Package p = samplePackage();
  p.material.shading = "lit";
  std::vector<uint8_t> bytes = expectStampedAndRoundTrips(p, 4);
  storeLE(bytes, 10, 3, 2);  // the same file as a 1.3 writer stamped it
  resealChecksum(bytes);
  const pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(r.formatMinor, 3u);
}

// Format 1.2: the Metal argument slots (section MSLB), written only when there are some, and
// then stamped 1.2 so that readers from before it refuse the package rather than lose the slots.
TEST(Package, MetalSlotsRoundTripAndStampFormatOneTwo) {
  pkg::Package p = samplePackage();
  const std::vector<uint8_t> without = pkg::write(p);
  EXPECT_EQ(loadLE(without, 10, 2), 1u);
  p.mslBindings = {{"FrameUniforms", pkg::MslResource::Buffer, 0, 0, 0},
                   {"facet_environment", pkg::MslResource::Texture, 1, 2, 2}};
  const std::vector<uint8_t> bytes = pkg::write(p);
  EXPECT_EQ(loadLE(bytes, 10, 2), 2u);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  EXPECT_EQ(r.formatMinor, 2u);
  EXPECT_EQ(pkg::write(*r.package), bytes);
}

TEST(Package, HostileMetalSlotsAreRejected) {
  pkg::Package p = samplePackage();
  p.mslBindings = {{"FrameUniforms", pkg::MslResource::Buffer, 0, 0, 0},
                   {"facet_environment", pkg::MslResource::Texture, 1, 2, 2}};
  const std::vector<uint8_t> good = pkg::write(p);
  const size_t mslb = sectionOffset(good, "MSLB");
  const size_t first = mslb + 4;                       // u32 count, then entries
  const size_t firstKind = first + 4 + 13;             // after "FrameUniforms"
  const size_t second = firstKind + 4 + 12;            // kind, reserved, set, binding, index
  const size_t secondIndex = second + 4 + 17 + 4 + 8;  // after "facet_environment", kind + reserved, set, binding
  auto hostile = [&](auto edit, const std::string& expectedPart) { expectEditRejected(good, edit, expectedPart); };
  hostile([&](auto& b) { storeLE(b, mslb, 0xFFFFFFFF, 4); }, "Metal binding count 4294967295");
  hostile([&](auto& b) { b[firstKind] = 7; }, "unknown kind 7");
  hostile([&](auto& b) { b[firstKind + 1] = 1; }, "reserved bits");
  hostile([&](auto& b) { b[first + 4] = '1'; }, "not an identifier");
  hostile([&](auto& b) { storeLE(b, secondIndex, 16, 4); }, "uses texture slot 16; Metal has 16");
  hostile([&](auto& b) { storeLE(b, 10, 1, 2); }, "only format 1.2 and later have");
  pkg::Package twice = p;
  twice.mslBindings[1].name = "FrameUniforms";
  twice.mslBindings[1].kind = pkg::MslResource::Buffer;
  expectRejected(pkg::write(twice), "names 'FrameUniforms' a second time");
  pkg::Package shared = p;
  shared.mslBindings[1].kind = pkg::MslResource::Buffer;
  shared.mslBindings[1].index = 0;
  expectRejected(pkg::write(shared), "reuses buffer slot 0");
}

// Sections follow each other at 8-byte boundaries with zero padding, the last ending the file:
// bytes anywhere else (a non-zero padding byte, a wider gap, a tail after the last section) are
// data no check reads, which a resealed hostile file could carry. They used to be accepted.
TEST(Package, PaddingAndBytesOutsideTheSectionsAreRejected) {
  const std::vector<uint8_t> good = pkg::write(samplePackage());
  ASSERT_TRUE(pkg::read(good).package);
  // The first gap between two sections (META's size is no multiple of 8 here).
  const size_t metaEnd = sectionOffset(good, "META") + size_t(loadLE(good, tocEntry(good, "META") + 16, 8));
  ASSERT_LT(metaEnd, sectionOffset(good, "VARS")) << "no padding after META to test";
  expectEditRejected(
      good, [&](auto& b) { b[metaEnd] = 0x5a; },
      "padding byte " + std::to_string(metaEnd) + " before section 'VARS' is 90, not zero");

  // Eight more zero bytes before BDAT, its entry and the file size moved to match.
  const size_t data = sectionOffset(good, "BDAT");
  expectEditRejected(
      good,
      [&](auto& b) {
        b.insert(b.begin() + long(data), 8, 0);
        storeLE(b, tocEntry(b, "BDAT") + 8, data + 8, 8);
        storeLE(b, 16, b.size(), 8);
      },
      "section 'BDAT' starts at byte " + std::to_string(data + 8) + ", but section 'BTAB' ends at byte");

  // Bytes after the last section, counted in the header's file size.
  expectEditRejected(
      good,
      [&](auto& b) {
        b.insert(b.end(), 16, 0);
        storeLE(b, 16, b.size(), 8);
      },
      "package has 16 bytes after its last section, which ends at byte " + std::to_string(good.size()));
}

// Every section, the optional ones included (META with every kind of parameter, VARS, TEXS,
// MSLB, PRSH, BTAB, BDAT with a dictionary), written and read back three ways: package::read
// gives the package back; PackageReader gives its table rows (each shader's slot and code, each
// texture's description and texels) field by field, with the Metal slots and the preshader; and
// writing what was read gives the same bytes. A field the conversions between the model and the
// rows (package/src/rows.h) drop, or a section forgets, fails here.
TEST(Package, RowsRoundTripEverySection) {
  pkg::Package p = samplePackage();
  p.material.doubleSided = true;
  p.material.params.push_back(
      {"albedo", pkg::ParamType::TextureSrgb, {1, 0.5, 0.25, 1}, std::nullopt, std::nullopt, 0, 0});
  p.material.params.push_back(
      {"bumps", pkg::ParamType::TextureNormal, {0.5, 0.5, 1, 1}, std::nullopt, std::nullopt, pkg::kNoTextureSlot, 0});
  p.mslBindings = pkg::mslBindingsFor(p.material);
  p.preshader.blockSize = 96;
  pkg::PreshaderProgram program;
  program.variants = {0, 2};
  program.ops = {{pkg::PreshaderOpcode::LoadParam, 1, 0, 0, 16, 3, {}},
                 {pkg::PreshaderOpcode::Constant, 2, 0, 0, 0, 0, {0.04f, 0.5f, -1.0f, 2.0f}},
                 {pkg::PreshaderOpcode::Mul, 3, 1, 2, 0, 0, {}},
                 {pkg::PreshaderOpcode::Clamp, 4, 3, 0, 0, 0, {0.0f, 1.0f, 0.0f, 0.0f}},
                 {pkg::PreshaderOpcode::Swizzle, 5, 4, 0, 0b11100100, 0, {}},
                 {pkg::PreshaderOpcode::Store, 0, 5, 0, 64, 4, {}}};
  p.preshader.programs = {program};

  const std::vector<uint8_t> bytes = pkg::write(p);
  pkg::ReadResult r = pkg::read(bytes);
  ASSERT_TRUE(r.package.has_value()) << r.error;
  EXPECT_EQ(*r.package, p);
  EXPECT_GT(r.dictionaryStoredSize, 0u);  // BDAT holds a dictionary blob too
  EXPECT_EQ(pkg::write(*r.package), bytes);

  std::string error;
  std::optional<pkg::PackageReader> reader = pkg::PackageReader::open(bytes, &error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->formatMinor(), 3u);
  EXPECT_EQ(reader->compilerVersion(), p.compilerVersion);
  EXPECT_EQ(reader->material(), p.material);
  EXPECT_EQ(reader->mslBindings(), p.mslBindings);
  EXPECT_EQ(reader->preshader(), p.preshader);
  ASSERT_EQ(reader->variants().size(), p.variants.size());
  for (size_t v = 0; v < p.variants.size(); ++v) {
    const pkg::VariantInfo& row = reader->variants()[v];
    EXPECT_EQ(row.key, p.variants[v].key);
    ASSERT_EQ(row.shaders.size(), p.variants[v].shaders.size());
    for (size_t s = 0; s < row.shaders.size(); ++s) {
      const pkg::Shader& shader = p.variants[v].shaders[s];
      EXPECT_EQ(row.shaders[s].stage, shader.stage);
      EXPECT_EQ(row.shaders[s].target, shader.target);
      auto code = reader->blob(row.shaders[s].blob, &error);
      ASSERT_TRUE(code) << error;
      EXPECT_TRUE(std::equal(code->begin(), code->end(), shader.code.begin(), shader.code.end()))
          << row.key << " " << s;
    }
  }
  ASSERT_EQ(reader->textures().size(), p.textures.size());
  for (size_t t = 0; t < p.textures.size(); ++t) {
    const pkg::TextureInfo& row = reader->textures()[t];
    const pkg::Texture& texture = p.textures[t];
    EXPECT_EQ(row.name, texture.name);
    EXPECT_EQ(row.width, texture.width);
    EXPECT_EQ(row.height, texture.height);
    EXPECT_EQ(row.format, texture.format);
    EXPECT_EQ(row.variants, texture.variants);
    auto texels = reader->texels(t, &error);
    ASSERT_TRUE(texels) << error;
    EXPECT_TRUE(std::equal(texels->begin(), texels->end(), texture.texels.begin(), texture.texels.end()));
  }

  // The fields compared one by one above, counted: a field added to a row or to the model does
  // not compile here until this test sets and compares it (Package, MaterialInfo, MslBinding
  // and Preshader compare whole, with their defaulted ==).
  [[maybe_unused]] const auto& [shaderStage, shaderTarget, shaderBlob] = pkg::ShaderInfo{};
  [[maybe_unused]] const auto& [variantKey, variantShaders] = pkg::VariantInfo{};
  [[maybe_unused]] const auto& [rowName, rowWidth, rowHeight, rowFormat, rowBlob, rowVariants] = pkg::TextureInfo{};
  [[maybe_unused]] const auto& [modelStage, modelTarget, modelCode] = pkg::Shader{};
  [[maybe_unused]] const auto& [modelKey, modelShaders] = pkg::Variant{};
  [[maybe_unused]] const auto& [name, width, height, format, texels, variants] = pkg::Texture{};
}
