// The compiled-variant cache (BuildOptions::cacheDir, matc compile --cache): same bytes, and only
// variants whose text changed are compiled again.
#include <gtest/gtest.h>

#include <filesystem>
#include <chrono>
#include <fstream>
#include <thread>

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

namespace {

uint64_t cacheBytes(const std::string& dir) {
  uint64_t total = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) total += entry.file_size();
  return total;
}

}  // namespace

// The cache is bounded: least recently used entries go first, so the material just rebuilt keeps
// its variants; temporary files of a killed process are removed once stale.
TEST(VariantCache, TrimKeepsTheMostRecentlyUsedVariantsWithinTheBound) {
  const std::string dir = facet::test::scratchDir("variant-cache-trim");
  std::string other = kMaterial;
  other.replace(other.find("roughness = params.roughness"), 28, "roughness = params.roughness * 0.5");  // other shader text
  auto a = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(a);
  const uint64_t oneMaterial = cacheBytes(dir);
  ASSERT_TRUE(facet::test::buildText(other, "other.mat", withCache(dir)));
  ASSERT_GT(cacheBytes(dir), oneMaterial);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // file times must order the uses
  const std::string stale = dir + "/ab/stale.tmp.1.2.3", fresh = dir + "/ab/fresh.tmp.1.2.3";
  fs::create_directories(dir + "/ab");
  std::ofstream(stale) << "partial";
  std::ofstream(fresh) << "partial";
  fs::last_write_time(stale, fs::file_time_type::clock::now() - std::chrono::hours(2));

  facet::compiler::BuildOptions bounded = withCache(dir);
  bounded.cacheMaxBytes = oneMaterial + 100;  // room for one material's variants (and the fresh temporary)
  auto again = facet::test::buildText(kMaterial, "test.mat", bounded);  // hits refresh its entries, then trims
  ASSERT_TRUE(again);
  EXPECT_EQ(again->cacheHits, again->package.variants.size());
  EXPECT_LE(cacheBytes(dir), bounded.cacheMaxBytes);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(fresh));
  auto warm = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(warm);
  EXPECT_EQ(warm->cacheHits, warm->package.variants.size()) << "the recently used material was trimmed";
  auto otherAgain = facet::test::buildText(other, "other.mat", withCache(dir));
  ASSERT_TRUE(otherAgain);
  EXPECT_LT(otherAgain->cacheHits, otherAgain->package.variants.size()) << "nothing of the older material was trimmed";
}
