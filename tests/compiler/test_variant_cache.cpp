// The compiled-variant cache (BuildOptions::cacheDir, matc compile --cache): same bytes, and only
// variants whose text changed are compiled again.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include <xxhash.h>

#include "facet/compiler/build.h"
#include "facet/package/package.h"
#include "test_compile.h"
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

// The cache's entries: <dir>/xx/<32 hex digits>.
std::vector<fs::path> entryFiles(const std::string& dir) {
  std::vector<fs::path> entries;
  for (const auto& folder : fs::directory_iterator(dir))
    if (fs::is_directory(folder.symlink_status()) && folder.path().filename().string().size() == 2)
      for (const auto& entry : fs::directory_iterator(folder.path()))
        if (entry.path().filename().string().size() == 32) entries.push_back(entry.path());
  std::sort(entries.begin(), entries.end());
  return entries;
}

// The first two-hex-digit entry-folder name that <dir> does not hold and is not `besides`.
std::string unusedEntryFolder(const std::string& dir, const std::string& besides = "") {
  const char* hex = "0123456789abcdef";
  for (int i = 0; i < 256; ++i) {
    const std::string name = {hex[i / 16], hex[i % 16]};
    if (name != besides && !fs::exists(fs::path(dir) / name)) return name;
  }
  return "";
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

// A SPIR-V-only build (BuildOptions::spirvOnly, matc eval's) keeps entries of its own: it neither
// takes a full build's entry (which holds code it does not ship) nor leaves its own where a full
// build would find a variant without GLSL ES or MSL.
TEST(VariantCache, SpirvOnlyAndFullBuildsKeepEntriesOfTheirOwn) {
  const std::string dir = facet::test::scratchDir("variant-cache-spirv-only");
  facet::compiler::BuildOptions full = withCache(dir), spirvOnly = withCache(dir);
  spirvOnly.spirvOnly = true;
  auto fullCold = facet::test::buildText(kMaterial, "test.mat", full);
  auto spirvCold = facet::test::buildText(kMaterial, "test.mat", spirvOnly);
  auto spirvWarm = facet::test::buildText(kMaterial, "test.mat", spirvOnly);
  auto fullWarm = facet::test::buildText(kMaterial, "test.mat", full);
  ASSERT_TRUE(fullCold && spirvCold && spirvWarm && fullWarm);
  EXPECT_EQ(spirvCold->cacheHits, 0u);
  EXPECT_EQ(spirvWarm->cacheHits, spirvWarm->package.variants.size());
  EXPECT_EQ(fullWarm->cacheHits, fullWarm->package.variants.size());
  EXPECT_EQ(entryFiles(dir).size(), 2 * fullCold->package.variants.size());
  EXPECT_EQ(facet::package::write(spirvWarm->package), facet::package::write(spirvCold->package));
  EXPECT_EQ(facet::package::write(fullWarm->package), facet::package::write(fullCold->package));
  for (const auto& v : spirvWarm->package.variants) EXPECT_EQ(v.shaders.size(), 2u) << v.key;
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
  for (const fs::path& entry : entryFiles(dir)) {
    if (damaged++ % 2 == 0) {
      fs::resize_file(entry, fs::file_size(entry) / 2);
    } else {
      std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
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

// Entries and temporary files (the marker is not counted).
uint64_t cacheBytes(const std::string& dir) {
  uint64_t total = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().parent_path() != fs::path(dir)) total += entry.file_size();
  return total;
}

}  // namespace

// The cache is bounded: least recently used entries go first, so the material just rebuilt keeps
// its variants; temporary files of a killed process are removed once stale.
TEST(VariantCache, TrimKeepsTheMostRecentlyUsedVariantsWithinTheBound) {
  const std::string dir = facet::test::scratchDir("variant-cache-trim");
  std::string other = kMaterial;
  other.replace(other.find("roughness = params.roughness"), 28,
                "roughness = params.roughness * 0.5");  // other shader text
  auto a = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(a);
  const uint64_t oneMaterial = cacheBytes(dir);
  ASSERT_TRUE(facet::test::buildText(other, "other.mat", withCache(dir)));
  ASSERT_GT(cacheBytes(dir), oneMaterial);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // file times must order the uses
  const std::string key = "ab" + std::string(30, '0');
  const std::string stale = dir + "/ab/" + key + ".tmp.Xy12zZ", fresh = dir + "/ab/" + key + ".tmp.1.2.3";
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

namespace {

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Where shader `index` of an entry starts ("FVC1", u32 count, then per shader u64 size + bytes,
// then XXH3-64 of all before it: variant_cache.cpp).
size_t shaderOffset(const std::string& entry, size_t index) {
  size_t at = 8;
  for (size_t i = 0;; ++i) {
    uint64_t size = 0;
    std::memcpy(&size, entry.data() + at, 8);
    if (i == index) return at + 8;
    at += 8 + size;
  }
}

// A new checksum over the edited bytes, as someone who read the format would write it.
void reseal(std::string* entry) {
  const uint64_t sum = XXH3_64bits(entry->data(), entry->size() - 8);
  std::memcpy(entry->data() + entry->size() - 8, &sum, 8);
}

}  // namespace

// An entry edited and resealed with a valid checksum gets past the checksum, not past the checks
// fresh output passes (spirv-val, glslang): it is a miss, the variant is compiled again, the
// package is what a build without the cache writes, and the entry is replaced.
TEST(VariantCache, AResealedEntryThatFailsValidationIsCompiledAgainAndReplaced) {
  const std::string dir = facet::test::scratchDir("variant-cache-resealed");
  facet::compiler::BuildOptions options = withCache(dir);
  options.tiers = {facet::permutations::Tier::High, facet::permutations::Tier::Mid};
  facet::compiler::BuildOptions uncachedOptions = options;
  uncachedOptions.cacheDir.clear();
  auto uncached = facet::test::buildText(kMaterial, "test.mat", uncachedOptions);
  ASSERT_TRUE(uncached && facet::test::buildText(kMaterial, "test.mat", options));
  const std::vector<fs::path> entries = entryFiles(dir);
  ASSERT_EQ(entries.size(), 4u);
  std::vector<std::string> original;
  for (const fs::path& e : entries) original.push_back(readBytes(e));

  std::string badSpirv = original[0];  // the fragment SPIR-V (shader 3) declares an id bound of 1
  const uint32_t bound = 1;
  std::memcpy(badSpirv.data() + shaderOffset(badSpirv, 3) + 12, &bound, 4);
  reseal(&badSpirv);
  writeBytes(entries[0], badSpirv);
  std::string badGlsl = original[1];  // the fragment GLSL ES (shader 1) has no main()
  const size_t main = badGlsl.find("main(", shaderOffset(badGlsl, 1));
  ASSERT_NE(main, std::string::npos);
  badGlsl.replace(main, 5, "mian(");
  reseal(&badGlsl);
  writeBytes(entries[1], badGlsl);

  auto again = facet::test::buildText(kMaterial, "test.mat", options);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->cacheRejected, 2u);
  EXPECT_EQ(again->cacheHits, 2u);
  EXPECT_TRUE(facet::package::write(again->package) == facet::package::write(uncached->package));
  EXPECT_TRUE(readBytes(entries[0]) == original[0]) << "the entry was not replaced";
  EXPECT_TRUE(readBytes(entries[1]) == original[1]) << "the entry was not replaced";
}

// The cache deletes what it holds, so it takes only a folder it can tell is its own; anything
// else is refused and left exactly as it was.
TEST(VariantCache, OnlyANewEmptyOrMarkedFolderIsTakenAsTheCache) {
  std::string error;
  const std::string fresh = facet::test::scratchDir("variant-cache-new") + "/a/b";
  EXPECT_TRUE(facet::compiler::prepareVariantCache(fresh, &error)) << error;
  EXPECT_EQ(facet::test::readText(fresh + "/facet-variant-cache").rfind("facet variant cache 1\n", 0), 0u);
  EXPECT_TRUE(facet::compiler::prepareVariantCache(fresh, &error)) << error;

  const std::string user = facet::test::scratchDir("variant-cache-user");
  std::ofstream(user + "/notes.txt") << "mine";
  EXPECT_FALSE(facet::compiler::prepareVariantCache(user, &error));
  EXPECT_NE(error.find("'" + user + "' is not a variant cache"), std::string::npos) << error;
  EXPECT_NE(error.find("notes.txt"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(user + "/facet-variant-cache"));
  EXPECT_FALSE(facet::compiler::prepareVariantCache(user + "/notes.txt", &error));
  EXPECT_NE(error.find("is not a folder"), std::string::npos) << error;

  const std::string other = facet::test::scratchDir("variant-cache-other-format");
  std::ofstream(other + "/facet-variant-cache") << "facet variant cache 2\n";
  EXPECT_FALSE(facet::compiler::prepareVariantCache(other, &error));
  EXPECT_NE(error.find("a variant cache of another format"), std::string::npos) << error;

  // A cache written before the marker existed holds entries only: it is kept, and marked.
  const std::string old = facet::test::scratchDir("variant-cache-unmarked");
  ASSERT_TRUE(facet::test::buildText(kMaterial, "test.mat", withCache(old)));
  fs::remove(old + "/facet-variant-cache");
  auto warm = facet::test::buildText(kMaterial, "test.mat", withCache(old));
  ASSERT_TRUE(warm);
  EXPECT_EQ(warm->cacheHits, warm->package.variants.size());
  EXPECT_TRUE(fs::exists(old + "/facet-variant-cache"));
}

// Trimming removes the cache's own entries and temporary files only: files of other names, in
// its folders or beside them, and whatever a link inside it leads to, stay.
TEST(VariantCache, TrimRemovesNothingButTheCachesOwnEntries) {
  const std::string dir = facet::test::scratchDir("variant-cache-foreign-files");
  ASSERT_TRUE(facet::test::buildText(kMaterial, "test.mat", withCache(dir)));
  // The foreign folders take entry-folder names the build did not use: which names it uses
  // follows the variants' hashes, which change with every chunk.
  const std::string linked = unusedEntryFolder(dir), plain = unusedEntryFolder(dir, linked);
  const std::string elsewhere = facet::test::scratchDir("variant-cache-elsewhere");
  const std::string key = linked + std::string(30, '0');
  std::ofstream(elsewhere + "/" + key) << "theirs";
  const std::string folder = dir + "/" + plain;
  fs::create_directory_symlink(elsewhere, dir + "/" + linked);
  fs::create_directories(folder);
  const std::vector<std::string> theirs = {dir + "/notes.txt",
                                           folder + "/notes.txt",
                                           folder + "/" + plain + std::string(30, '1') + ".bak",
                                           folder + "/draft.tmp.1.2.3",
                                           dir + "/AB" + std::string(30, '2'),
                                           elsewhere + "/" + key};
  for (const std::string& f : theirs) {
    if (!fs::exists(f)) std::ofstream(f) << "theirs";
    fs::last_write_time(f, fs::file_time_type::clock::now() - std::chrono::hours(2));
  }
  facet::compiler::BuildOptions bounded = withCache(dir);
  bounded.cacheMaxBytes = 1;  // every entry goes
  ASSERT_TRUE(facet::test::buildText(kMaterial, "test.mat", bounded));
  EXPECT_TRUE(entryFiles(dir).empty()) << entryFiles(dir).size();
  for (const std::string& f : theirs) EXPECT_EQ(facet::test::readText(f), "theirs") << f;
}

// An entry folder that is a link to a folder elsewhere is not the cache's: its entries are
// neither read (nor their times refreshed) nor written, and what is there stays as it was.
TEST(VariantCache, AnEntryFolderThatLinksElsewhereIsNeitherReadNorWritten) {
  const std::string dir = facet::test::scratchDir("variant-cache-linked-folder");
  auto cold = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(cold);
  const fs::path folder = entryFiles(dir).front().parent_path();
  const size_t linked = size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
  const std::string elsewhere =
      facet::test::scratchDir("variant-cache-linked-target") + "/" + folder.filename().string();
  fs::rename(folder, elsewhere);
  fs::create_directory_symlink(elsewhere, folder);
  std::vector<std::pair<fs::path, std::string>> before;
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(2);
  for (const auto& e : fs::directory_iterator(elsewhere)) {
    fs::last_write_time(e.path(), old);
    before.push_back({e.path(), readBytes(e.path())});
  }
  auto again = facet::test::buildText(kMaterial, "test.mat", withCache(dir));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->cacheHits, again->package.variants.size() - linked);
  EXPECT_EQ(size_t(std::distance(fs::directory_iterator(elsewhere), fs::directory_iterator())), before.size());
  for (const auto& [path, bytes] : before) {
    EXPECT_TRUE(readBytes(path) == bytes) << path;
    EXPECT_EQ(fs::last_write_time(path), old) << path;
  }
}
