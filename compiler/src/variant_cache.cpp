#include "variant_cache.h"

#include <xxhash.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace facet::compiler {
namespace {

namespace fs = std::filesystem;

// Entry: "FVC1", u32 shader count, per shader u64 size + bytes, then XXH3-64 of all before it.
constexpr char kMagic[4] = {'F', 'V', 'C', '1'};

void appendLE(std::string& out, uint64_t v, int n) {
  for (int i = 0; i < n; ++i) out += char(uint8_t(v >> (8 * i)));
}

uint64_t loadLE(const char* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= uint64_t(uint8_t(p[i])) << (8 * i);
  return v;
}

}  // namespace

std::string variantCacheKey(const std::string& compilerVersion, const StageSources& es, const StageSources& vulkan,
                            bool fp16Emulation) {
  // Length-prefixed fields, so no two different inputs concatenate to the same bytes.
  std::string input;
  for (const std::string* field : {&compilerVersion, &es.vertex, &es.fragment, &vulkan.vertex, &vulkan.fragment}) {
    appendLE(input, field->size(), 8);
    input += *field;
  }
  input += fp16Emulation ? '1' : '0';
  // What the backends make of the same sources, for entries written by earlier builds of the
  // same version: 2 = MSL resource slots pinned from shader_abi.h.
  input += "backends 2";
  XXH128_hash_t h = XXH3_128bits(input.data(), input.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return hex;
}

std::string VariantCache::path(const std::string& key) const { return dir_ + "/" + key.substr(0, 2) + "/" + key; }

std::optional<CompiledShaders> VariantCache::load(const std::string& key) const {
  if (dir_.empty()) return std::nullopt;
  std::ifstream in(path(key), std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  const std::string bytes = s.str();
  if (bytes.size() < 16 || std::memcmp(bytes.data(), kMagic, 4) != 0) return std::nullopt;
  const size_t body = bytes.size() - 8;
  if (XXH3_64bits(bytes.data(), body) != loadLE(bytes.data() + body, 8)) return std::nullopt;
  if (loadLE(bytes.data() + 4, 4) != 6) return std::nullopt;
  CompiledShaders shaders;
  size_t at = 8;
  for (std::vector<uint8_t>& shader : shaders) {
    if (body - at < 8) return std::nullopt;
    uint64_t size = loadLE(bytes.data() + at, 8);
    at += 8;
    if (size > body - at) return std::nullopt;
    shader.assign(bytes.begin() + long(at), bytes.begin() + long(at + size));
    at += size;
  }
  if (at != body) return std::nullopt;
  return shaders;
}

void VariantCache::store(const std::string& key, const CompiledShaders& shaders) const {
  if (dir_.empty()) return;
  std::string bytes(kMagic, 4);
  appendLE(bytes, shaders.size(), 4);
  for (const std::vector<uint8_t>& shader : shaders) {
    appendLE(bytes, shader.size(), 8);
    bytes.append(shader.begin(), shader.end());
  }
  appendLE(bytes, XXH3_64bits(bytes.data(), bytes.size()), 8);

  std::error_code ec;
  const std::string target = path(key);
  fs::create_directories(fs::path(target).parent_path(), ec);
  if (ec) return;
  static std::atomic<uint64_t> counter{0};
  const std::string temp = target + ".tmp." + std::to_string(getpid()) + "." + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) +
                           "." + std::to_string(counter++);
  {
    std::ofstream out(temp, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) {
      fs::remove(temp, ec);
      return;
    }
  }
  fs::rename(temp, target, ec);
  if (ec) fs::remove(temp, ec);
}

}  // namespace facet::compiler
