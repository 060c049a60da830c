// Content-addressed on-disk cache of compiled variants (matc compile --cache). The key is a hash
// of everything a variant's compiled output depends on: the compiler version and build identity
// (below), both flavours of
// the assembled GLSL (which already contain the material's surface program, the tier's choices
// and every chunk's text) and the options that change the output. Editing one chunk changes the
// text, hence the key, of exactly the variants that include it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/compiler/assemble.h"

namespace facet::compiler {

// A variant's six shaders, in package order: GLSL ES vertex, fragment; SPIR-V vertex, fragment;
// MSL vertex, fragment.
using CompiledShaders = std::array<std::vector<uint8_t>, 6>;

// What else a compiled variant depends on: a hash of the compiler's own code taken at build time
// (cmake/HashSources.cmake) and the versions of glslang, SPIRV-Tools and SPIRV-Cross. Without it
// a rebuilt compiler (or an upgraded Debian library) would reuse variants an older one compiled
// from the same GLSL text.
const std::string& compilerBuildIdentity();

// The build options (BuildOptions) that change a variant's compiled output beyond its text.
struct VariantOutputOptions {
  bool fp16Emulation = false;
  bool fp16TrueHalf = false;
  bool spirvOnly = false;  // the entry holds the two SPIR-V stages alone (the other slots empty)
};

// 32 hex digits (XXH3-128) naming a variant's compiled output.
std::string variantCacheKey(const std::string& compilerVersion, const StageSources& es, const StageSources& vulkan,
                            const VariantOutputOptions& output);

// The folder is the cache's own (prepareVariantCache, build.h): its marker file, entries
// dir/xx/<key> (xx: the key's first two digits) and their temporary files dir/xx/<key>.tmp.*.
// The cache reads, writes and deletes those names only. `dir` empty: every load misses and
// nothing is stored. Entries are written to a temporary name and renamed, so concurrent jobs or
// processes never see half an entry; an entry that does not check (truncated, damaged, larger
// than kMaxEntryBytes, not a regular file) is a miss. Safe to use from several threads.
class VariantCache {
 public:
  explicit VariantCache(std::string dir) : dir_(std::move(dir)) {}
  std::optional<CompiledShaders> load(const std::string& key) const;
  // Best effort: a cache that cannot be written only costs the next build time.
  void store(const std::string& key, const CompiledShaders& shaders) const;

  // Bounds the cache: removes entries least recently used first (a hit refreshes an entry's
  // modification time) until at most maxBytes remain, and the cache's temporary files more than
  // an hour old (left by a process that was killed mid-store). Concurrent builds may trim at
  // once: a removed entry is only a miss for whoever wanted it. Returns the bytes removed.
  uint64_t trim(uint64_t maxBytes) const;

 private:
  std::string path(const std::string& key) const;
  std::string dir_;
};

// An entry holds one variant's six shaders: the example materials' largest is 47,885 bytes
// (painted_tiles with four point lights), so 64 MiB (1,400 times that) refuses no real variant,
// while a planted file of any size is a miss before it is read. A variant larger than this is
// compiled every time, never stored.
inline constexpr uint64_t kMaxEntryBytes = uint64_t(64) << 20;

}  // namespace facet::compiler
