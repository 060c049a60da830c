// The compiled-variant cache (BuildOptions::cacheDir, matc compile --cache): same bytes, and only
// variants whose text changed are compiled again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "facet/compiler/build.h"
#include "facet/package.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

const char* kMaterial = R"(material cached {
    shading lit
    param roughness: float = 0.4 in [0, 1]
    surface { roughness = params.roughness }
})";

facet::compiler::BuildOptions withCache(const std::string& dir) {
  facet::compiler::BuildOptions options;
  options.cacheDir = dir;
  return options;
}

}  // namespace

TEST(VariantCache, WarmBuildTakesEveryVariantFromTheCacheAndWritesTheSameBytes) {
  const std::string dir = facet::test::scratchDir("variant-cache-warm");
  auto uncached = facet::test::buildText(kMaterial);
  auto cold = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  auto warm = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(uncached && cold && warm);
  EXPECT_EQ(cold->cacheHits, 0u);
  EXPECT_EQ(warm->cacheHits, warm->package.variants.size());
  const auto bytes = facet::package::write(uncached->package);
  EXPECT_EQ(facet::package::write(cold->package), bytes);
  EXPECT_EQ(facet::package::write(warm->package), bytes);
}

// A change that reaches one tier's text (here a tier override; a chunk only that tier includes
// behaves alike) compiles that tier's variants again and takes the others from the cache.
TEST(VariantCache, ChangingOneTiersTextRecompilesOnlyThatTiersVariants) {
  const std::string dir = facet::test::scratchDir("variant-cache-edit");
  facet::compiler::BuildOptions options = withCache(dir);
  options.tiers = {facet::permutations::Tier::High, facet::permutations::Tier::Mid};
  ASSERT_TRUE(facet::test::buildText(kMaterial, "test.mat", options));
  std::string edited = kMaterial;
  edited.insert(edited.find("    surface"), "    tier high { specular = ggx_fastv }\n");
  auto rebuilt = facet::test::buildText(edited, "test.mat", options);
  ASSERT_TRUE(rebuilt);
  size_t mid = 0;
  for (const auto& v : rebuilt->package.variants) mid += v.key.rfind("mid.", 0) == 0 ? 1 : 0;
  EXPECT_EQ(rebuilt->cacheHits, mid);
  EXPECT_GT(mid, 0u);
  EXPECT_LT(mid, rebuilt->package.variants.size());
}

// Damaged entries are misses, compiled again and rewritten, never trusted.
TEST(VariantCache, DamagedEntriesAreCompiledAgain) {
  const std::string dir = facet::test::scratchDir("variant-cache-damaged");
  auto cold = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(cold);
  size_t damaged = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    if (damaged++ % 2 == 0) {
      fs::resize_file(entry.path(), fs::file_size(entry.path()) / 2);
    } else {
      std::fstream f(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(40);
      f.put('\x7f');
    }
  }
  ASSERT_EQ(damaged, cold->package.variants.size());
  auto again = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->cacheHits, 0u);
  EXPECT_EQ(facet::package::write(again->package), facet::package::write(cold->package));
  auto warm = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(warm);
  EXPECT_EQ(warm->cacheHits, warm->package.variants.size());
}
