// The package loader apps use (package::PackageReader, runtime::LoadedMaterial): packages from
// memory, lazy decompression, bounded hostile input. Byte-level format checks: test_package.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>

#include <xxhash.h>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"
#include "facet/runtime/material.h"
#include "test_support.h"

namespace pkg = facet::package;

namespace {

std::vector<uint8_t> fileBytes(const std::string& path) {
  std::string text = facet::test::readText(path);
  return {text.begin(), text.end()};
}

// The example packages, built by matc with the build (tests/package/CMakeLists.txt); read only.
std::string packageDir() { return FACET_EXAMPLE_PACKAGES; }

// The header's checksum (bytes 24..31: XXH3-64 of the file with those bytes zero) recomputed, so
// damage reaches the checks behind it (docs/package-format.md).
void reseal(std::vector<uint8_t>& b) {
  std::memset(&b[24], 0, 8);
  const uint64_t sum = XXH3_64bits(b.data(), b.size());
  for (int i = 0; i < 8; ++i) b[24 + i] = uint8_t(sum >> (8 * i));
}

// Where section `tag` starts (header: u32 section count at byte 12; 24-byte TOC entries from
// byte 32: tag, flags, u64 offset, u64 size).
uint64_t sectionOffset(const std::vector<uint8_t>& b, const char* tag) {
  uint32_t count = 0;
  std::memcpy(&count, &b[12], 4);
  for (uint32_t i = 0; i < count; ++i) {
    const size_t at = 32 + 24 * size_t(i);
    if (std::memcmp(&b[at], tag, 4) != 0) continue;
    uint64_t offset = 0;
    std::memcpy(&offset, &b[at + 8], 8);
    return offset;
  }
  ADD_FAILURE() << "no section " << tag;
  return 0;
}

// The blobs one variant's shaders need.
std::set<uint32_t> blobsOf(const pkg::VariantInfo& v, bool withMsl) {
  std::set<uint32_t> out;
  for (const pkg::ShaderInfo& s : v.shaders) {
    if (!withMsl && s.target == pkg::Target::Msl) continue;
    out.insert(s.blob);
  }
  return out;
}

}  // namespace

TEST(PackageLoader, PackageFromMemoryEqualsPackageFromFile) {
  for (const std::string name : {"red_plastic", "painted_tiles", "brushed_gold"}) {
    const std::string path = packageDir() + "/" + name + ".matpkg";
    const std::vector<uint8_t> bytes = fileBytes(path);
    std::string error;
    auto fromFile = pkg::PackageReader::openFile(path, &error);
    ASSERT_TRUE(fromFile) << error;
    auto fromMemory = pkg::PackageReader::open(bytes, &error);
    ASSERT_TRUE(fromMemory) << error;
    EXPECT_EQ(fromMemory->compilerVersion(), fromFile->compilerVersion());
    EXPECT_EQ(fromMemory->material(), fromFile->material());
    ASSERT_EQ(fromMemory->variants().size(), fromFile->variants().size());
    ASSERT_FALSE(fromMemory->variants().empty());

    // And both equal what package::read (the tools' whole-package view) makes of the same bytes.
    pkg::ReadResult whole = pkg::read(bytes);
    ASSERT_TRUE(whole.package) << whole.error;
    EXPECT_EQ(fromMemory->material(), whole.package->material);
    for (size_t v = 0; v < whole.package->variants.size(); ++v) {
      const pkg::Variant& expected = whole.package->variants[v];
      EXPECT_EQ(fromMemory->variants()[v].key, expected.key);
      EXPECT_EQ(fromFile->variants()[v].key, expected.key);
      for (const pkg::Shader& s : expected.shaders) {
        auto a = fromMemory->shader(expected.key, s.stage, s.target, &error);
        ASSERT_TRUE(a) << error;
        auto b = fromFile->shader(expected.key, s.stage, s.target, &error);
        ASSERT_TRUE(b) << error;
        EXPECT_TRUE(std::equal(a->begin(), a->end(), s.code.begin(), s.code.end())) << name << " " << expected.key;
        EXPECT_TRUE(std::equal(b->begin(), b->end(), s.code.begin(), s.code.end())) << name << " " << expected.key;
      }
    }

    // The runtime's two entry points give the same programs.
    auto loaded = facet::runtime::LoadedMaterial::load(path, &error);
    ASSERT_TRUE(loaded) << error;
    auto inMemory = facet::runtime::LoadedMaterial::loadFromMemory(bytes, name, &error);
    ASSERT_TRUE(inMemory) << error;
    EXPECT_EQ(inMemory->info(), loaded->info());
    for (const pkg::VariantInfo& v : loaded->reader().variants()) {
      auto p = loaded->program(v.key, &error);
      ASSERT_TRUE(p) << error;
      auto q = inMemory->program(v.key, &error);
      ASSERT_TRUE(q) << error;
      EXPECT_EQ(p->vertexSpirv, q->vertexSpirv);
      EXPECT_EQ(p->fragmentSpirv, q->fragmentSpirv);
      EXPECT_EQ(p->vertexGlslEs, q->vertexGlslEs);
      EXPECT_EQ(p->fragmentGlslEs, q->fragmentGlslEs);
      EXPECT_FALSE(p->fragmentSpirv.empty());
    }
  }
}

// Bytes zstd writes to draw one variant: what program() needs and nothing of the other variants.
// Prints the figure against package::read (every blob), the loader before the lazy reader.
TEST(PackageLoader, LazyReadDecompressesOnlyTheAskedVariant) {
  const std::string path = packageDir() + "/red_plastic.matpkg";
  const std::vector<uint8_t> bytes = fileBytes(path);
  std::string error;
  auto material = facet::runtime::LoadedMaterial::loadFromMemory(bytes, "red_plastic", &error);
  ASSERT_TRUE(material) << error;
  const pkg::PackageReader& reader = material->reader();
  EXPECT_EQ(reader.bytesDecompressed(), 0u);  // opening decodes tables only
  ASSERT_GE(reader.variants().size(), 2u);
  const pkg::VariantInfo* variant = reader.findVariant("high.dir1");
  ASSERT_TRUE(variant);

  ASSERT_TRUE(material->program("high.dir1", &error)) << error;
  // Expected: the compressed blobs of its GLSL ES and SPIR-V shaders, each once, plus the
  // dictionary they are coded against (MSL stays compressed: this runtime has no Metal backend).
  std::set<uint32_t> needed = blobsOf(*variant, false);
  pkg::ReadResult whole = pkg::read(bytes);
  ASSERT_TRUE(whole.package) << whole.error;
  uint64_t expected = 0, everything = 0;
  std::set<uint32_t> dictionaries;
  for (uint32_t b = 0; b < reader.blobs().size(); ++b)
    if (reader.blobs()[b].compressed) everything += reader.blobs()[b].rawSize;
  for (uint32_t b : needed)
    if (reader.blobs()[b].compressed) expected += reader.blobs()[b].rawSize;
  // The dictionary is the one blob no shader and no texture uses (format 1.1).
  std::set<uint32_t> used;
  for (const pkg::VariantInfo& v : reader.variants())
    for (const pkg::ShaderInfo& s : v.shaders) used.insert(s.blob);
  for (const pkg::TextureInfo& t : reader.textures()) used.insert(t.blob);
  for (uint32_t b = 0; b < reader.blobs().size(); ++b)
    if (!used.count(b) && reader.blobs()[b].compressed) expected += reader.blobs()[b].rawSize;
  EXPECT_EQ(reader.bytesDecompressed(), expected);
  EXPECT_LT(reader.bytesDecompressed(), everything);

  // Asking again decodes nothing more: the blobs are kept.
  ASSERT_TRUE(material->program("high.dir1", &error)) << error;
  EXPECT_EQ(reader.bytesDecompressed(), expected);
  std::printf(
      "red_plastic: bytes decompressed to draw high.dir1: %llu lazily, %llu by package::read (all %zu variants)\n",
      static_cast<unsigned long long>(reader.bytesDecompressed()), static_cast<unsigned long long>(everything),
      reader.variants().size());
}

TEST(PackageLoader, RawBlobsAreServedFromTheAppsBytesWithoutACopy) {
  // Random bytes do not compress: the writer stores them raw (one shader blob: no dictionary).
  pkg::Package p;
  p.compilerVersion = "test";
  p.material.name = "m";
  p.material.shading = "lit";
  p.material.blending = "opaque";
  std::mt19937 rng(7);
  std::vector<uint8_t> noise(4096);
  for (uint8_t& c : noise) c = uint8_t(rng());
  p.variants.push_back({"high.dir1", {{pkg::Stage::Vertex, pkg::Target::Spirv, noise}}});
  const std::vector<uint8_t> bytes = pkg::write(p);
  std::string error;
  auto reader = pkg::PackageReader::open(bytes, &error);
  ASSERT_TRUE(reader) << error;
  ASSERT_EQ(reader->blobs().size(), 1u);
  ASSERT_FALSE(reader->blobs()[0].compressed);
  auto raw = reader->shader("high.dir1", pkg::Stage::Vertex, pkg::Target::Spirv, &error);
  ASSERT_TRUE(raw) << error;
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), noise.begin(), noise.end()));
  EXPECT_TRUE(raw->data() >= bytes.data() && raw->data() + raw->size() <= bytes.data() + bytes.size());
  EXPECT_EQ(reader->bytesDecompressed(), 0u);

  // Compressed blobs are decoded into the reader's own memory.
  const std::vector<uint8_t> red = fileBytes(packageDir() + "/red_plastic.matpkg");
  auto compressed = pkg::PackageReader::open(red, &error);
  ASSERT_TRUE(compressed) << error;
  for (uint32_t b = 0; b < compressed->blobs().size(); ++b) {
    auto code = compressed->blob(b, &error);
    ASSERT_TRUE(code) << error;
    const bool inside = code->data() >= red.data() && code->data() + code->size() <= red.data() + red.size();
    EXPECT_EQ(inside, !compressed->blobs()[b].compressed) << "blob " << b;
  }
}

// A damaged blob is found when its variant is asked for, and spoils nothing else.
TEST(PackageLoader, DamagedBlobFailsOnlyTheVariantThatNeedsIt) {
  const std::vector<uint8_t> good = fileBytes(packageDir() + "/red_plastic.matpkg");
  std::string error;
  auto reader = pkg::PackageReader::open(good, &error);
  ASSERT_TRUE(reader) << error;
  const pkg::VariantInfo* high = reader->findVariant("high.dir1");
  ASSERT_TRUE(high);
  // A blob only high.dir1 uses.
  std::set<uint32_t> others;
  for (const pkg::VariantInfo& v : reader->variants())
    if (v.key != high->key)
      for (const pkg::ShaderInfo& s : v.shaders) others.insert(s.blob);
  const pkg::ShaderInfo* own = nullptr;
  for (const pkg::ShaderInfo& s : high->shaders)
    if (!others.count(s.blob)) own = &s;
  ASSERT_TRUE(own) << "every blob of high.dir1 is shared";

  // Its content hash in the blob table (BTAB: u32 count, then 40-byte entries, hash first) is
  // wrong, and the checksum resealed: the tables still parse, the blob no longer verifies.
  std::vector<uint8_t> bad = good;
  const uint64_t entry = sectionOffset(good, "BTAB") + 4 + 40 * uint64_t(own->blob);
  bad[entry] ^= 0x01;
  reseal(bad);
  auto damaged = pkg::PackageReader::open(bad, &error);
  ASSERT_TRUE(damaged) << "tables are intact, open() must succeed: " << error;
  EXPECT_FALSE(damaged->shader(high->key, own->stage, own->target, &error));
  EXPECT_NE(error.find("content hash mismatch"), std::string::npos) << error;
  for (const pkg::VariantInfo& v : damaged->variants()) {
    if (v.key == high->key) continue;
    for (const pkg::ShaderInfo& s : v.shaders) EXPECT_TRUE(damaged->shader(v.key, s.stage, s.target, &error)) << error;
  }
}

// Hostile bytes reach open() and every blob request, not only package::read: never a crash,
// always an answer (ASan checks allocations sized from the damage).
TEST(PackageLoader, RandomDamageWithValidChecksumNeverCrashesTheLazyPath) {
  const std::vector<uint8_t> good = fileBytes(packageDir() + "/brushed_gold.matpkg");
  std::mt19937 rng(99);
  for (int round = 0; round < 1500; ++round) {
    std::vector<uint8_t> b = good;
    int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      size_t at = 32 + rng() % (b.size() - 32);
      b[at] = (rng() % 2) ? uint8_t(rng()) : uint8_t(b[at] ^ 0xFF);
    }
    reseal(b);
    std::string error;
    auto r = pkg::PackageReader::open(b, &error);
    if (!r) {
      ASSERT_FALSE(error.empty());
      continue;
    }
    (void)r->semanticError();
    for (const pkg::VariantInfo& v : r->variants())
      for (const pkg::ShaderInfo& s : v.shaders) {
        error.clear();
        if (!r->shader(v.key, s.stage, s.target, &error)) {
          ASSERT_FALSE(error.empty());
        }
      }
    for (size_t t = 0; t < r->textures().size(); ++t) {
      error.clear();
      if (!r->texels(t, &error)) {
        ASSERT_FALSE(error.empty());
      }
    }
  }
}

// The bound lives in package::semanticError (one owner); the loader runs it before anything
// sized from the block exists.
TEST(PackageLoader, DeclaredFourGiBParameterBlockIsRefusedOnLoadFromMemory) {
  pkg::ReadResult whole = pkg::readFile(packageDir() + "/red_plastic.matpkg");
  ASSERT_TRUE(whole.package) << whole.error;
  pkg::Package p = *whole.package;
  p.material.paramBlockSize = 0xffffffffu;
  const std::vector<uint8_t> bytes = pkg::write(p);
  std::string error;
  auto reader = pkg::PackageReader::open(bytes, &error);
  ASSERT_TRUE(reader) << "the bytes are well formed; the meaning is not: " << error;
  EXPECT_NE(reader->semanticError().find("the parameter block is 4294967295 bytes; the limit is 4096"),
            std::string::npos);
  EXPECT_FALSE(facet::runtime::LoadedMaterial::loadFromMemory(bytes, "app-bytes", &error));
  EXPECT_EQ(error.rfind("app-bytes: the parameter block is 4294967295 bytes", 0), 0u) << error;
}

TEST(PackageLoader, UnknownVariantAndMissingShaderAreErrors) {
  const std::vector<uint8_t> bytes = fileBytes(packageDir() + "/red_plastic.matpkg");
  std::string error;
  auto reader = pkg::PackageReader::open(bytes, &error);
  ASSERT_TRUE(reader) << error;
  EXPECT_FALSE(reader->shader("ultra.dir9", pkg::Stage::Vertex, pkg::Target::Spirv, &error));
  EXPECT_EQ(error, "the package has no variant 'ultra.dir9'");
  EXPECT_FALSE(reader->texels(1000, &error));
  EXPECT_NE(error.find("texture 1000 does not exist"), std::string::npos);
  EXPECT_EQ(reader->bytesDecompressed(), 0u);
}

// The parameter layout itself is meaning (package::semanticError, run by the loader): std140
// places, no two parameters sharing a byte (paramBlock() wrote one over the other), a block ending
// where the parameters do, rounded to 16 (the preshader's derived members start there), no two
// textures on one sampler slot. Each used to load.
TEST(PackageLoader, ParameterLayoutIsStd140WithoutOverlaps) {
  pkg::ReadResult whole = pkg::readFile(packageDir() + "/red_plastic.matpkg");
  ASSERT_TRUE(whole.package) << whole.error;
  const pkg::Package good = *whole.package;
  ASSERT_EQ(good.material.params[0].name, "baseColor");    // colour at 0..12
  ASSERT_EQ(good.material.params[1].name, "roughness");    // float at 12..16
  ASSERT_EQ(good.material.params[2].name, "reflectance");  // float at 16..20, block 32
  auto refusal = [](const pkg::Package& p) {
    const std::vector<uint8_t> bytes = pkg::write(p);
    std::string error;
    EXPECT_FALSE(facet::runtime::LoadedMaterial::loadFromMemory(bytes, "app-bytes", &error));
    return error;
  };
  auto expectRefused = [&](auto edit, const std::string& why) {
    pkg::Package p = good;
    edit(p);
    EXPECT_EQ(pkg::semanticError(p).find(why), 0u) << pkg::semanticError(p);
    EXPECT_EQ(refusal(p), "app-bytes: " + pkg::semanticError(p));
  };
  expectRefused([](pkg::Package& p) { p.material.params[1].offset = 8; },
                "parameters 'baseColor' (bytes 0..12) and 'roughness' (bytes 8..12) overlap");
  expectRefused([](pkg::Package& p) { p.material.params[2].offset = 12; },
                "parameters 'roughness' (bytes 12..16) and 'reflectance' (bytes 12..16) overlap");
  expectRefused([](pkg::Package& p) { p.material.params[2].offset = 18; },
                "parameter 'reflectance': byte offset 18 is not a multiple of its std140 alignment, 4");
  expectRefused([](pkg::Package& p) { p.material.params[0].offset = 4; },
                "parameter 'baseColor': byte offset 4 is not a multiple of its std140 alignment, 16");
  expectRefused([](pkg::Package& p) { p.material.paramBlockSize = 48; },
                "the parameter block is 48 bytes, but its parameters end at byte 20, which std140 rounds to 32");

  pkg::ReadResult tiles = pkg::readFile(packageDir() + "/painted_tiles.matpkg");
  ASSERT_TRUE(tiles.package) << tiles.error;
  pkg::Package sharedSlot = *tiles.package;
  ASSERT_TRUE(pkg::isTexture(sharedSlot.material.params[1].type));
  sharedSlot.material.params[1].offset = sharedSlot.material.params[0].offset;
  EXPECT_EQ(pkg::semanticError(sharedSlot), "parameter 'relief': sampler slot 0 is another texture parameter's");
}

// The Metal slots (section MSLB) agree with what the package declares: each names a block or
// sampler of the material at the slot shader_abi.h pins, and each such resource has one. The
// reader checks kinds, ranges and uniqueness; a slot table that named a block the material has
// not, or moved a sampler, was accepted.
TEST(PackageLoader, MetalSlotsAgreeWithTheMaterial) {
  pkg::ReadResult whole = pkg::readFile(packageDir() + "/painted_tiles.matpkg");
  ASSERT_TRUE(whole.package) << whole.error;
  const pkg::Package good = *whole.package;
  // painted_tiles' tuned high lights its diffuse from the irradiance cube (its tuning file), so the
  // package pins the cube's slot too.
  ASSERT_EQ(good.mslBindings, pkg::mslBindingsFor(good.material, false, true));
  auto expectRefused = [&](auto edit, const std::string& why) {
    pkg::Package p = good;
    edit(p);
    EXPECT_EQ(pkg::semanticError(p), why);
    std::string error;
    const std::vector<uint8_t> bytes = pkg::write(p);
    EXPECT_FALSE(facet::runtime::LoadedMaterial::loadFromMemory(bytes, "app-bytes", &error));
    EXPECT_EQ(error, "app-bytes: " + why);
  };
  auto find = [](pkg::Package& p, const std::string& name) -> pkg::MslBinding& {
    for (pkg::MslBinding& b : p.mslBindings)
      if (b.name == name) return b;
    ADD_FAILURE() << "no Metal binding " << name;
    return p.mslBindings[0];
  };
  expectRefused([&](pkg::Package& p) { find(p, "facet_material_relief").index = 12; },
                "Metal binding 'facet_material_relief' is texture(12) for Vulkan set 1 binding 9; the shader interface "
                "pins it at texture(9) for set 1 binding 9");
  expectRefused(
      [&](pkg::Package& p) { find(p, "MaterialParams").binding = 5; },
      "Metal binding 'MaterialParams' is buffer(2) for Vulkan set 0 binding 5; the shader interface pins it at "
      "buffer(2) for set 0 binding 2");
  expectRefused(
      [&](pkg::Package& p) {
        find(p, "facet_environment").kind = pkg::MslResource::Buffer;
        find(p, "facet_environment").index = 7;
      },
      "Metal binding 'facet_environment' is buffer(7) for Vulkan set 1 binding 2; the shader interface pins it at "
      "texture(2) for set 1 binding 2");
  expectRefused(
      [&](pkg::Package& p) { find(p, "facet_material_albedo").name = "facet_material_gloss"; },
      "Metal binding 'facet_material_gloss' (texture(8)) names no block or sampler of this material's shaders");
  expectRefused(
      [&](pkg::Package& p) { std::erase_if(p.mslBindings, [](auto& b) { return b.name == "ObjectUniforms"; }); },
      "the Metal slots do not place 'ObjectUniforms', which the material's shaders declare");
  // No slots at all is a package from before format 1.2: nothing to check.
  pkg::Package none = good;
  none.mslBindings.clear();
  EXPECT_EQ(pkg::semanticError(none), "");
}
