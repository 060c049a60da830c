// bytes -> Package, for tools (matc info, the writer's round trip): the lazy PackageReader with
// every blob requested, so there is one parser of the format.
#include <exception>
#include <new>

#include "facet/package/package_reader.h"
#include "format.h"
#include "rows.h"

namespace facet::package {

using namespace detail;

namespace {

ReadResult failure(std::string error) {
  ReadResult r;
  r.error = std::move(error);
  return r;
}

ReadResult readChecked(std::span<const uint8_t> file) {
  std::string error;
  std::optional<PackageReader> reader = PackageReader::open(file, &error);
  if (!reader) return failure(error);
  const std::vector<VariantInfo>& variants = reader->variants();
  const std::vector<TextureInfo>& textures = reader->textures();
  const std::vector<BlobInfo>& blobs = reader->blobs();

  // Shared blobs are copied into every shader that uses them, so the copies are what must stay
  // bounded, not just the stored bytes.
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> users(blobs.size());
  uint64_t totalCode = 0;
  for (uint32_t v = 0; v < variants.size(); ++v) {
    for (uint32_t s = 0; s < variants[v].shaders.size(); ++s) {
      uint32_t blob = variants[v].shaders[s].blob;
      totalCode += blobs[blob].rawSize;
      if (totalCode > kMaxTotalCodeSize)
        return failure("variants up to '" + variants[v].key + "' hold more than " + std::to_string(kMaxTotalCodeSize) +
                       " bytes of shader code in total");
      users[blob].push_back({v, s});
    }
  }
  // Texels are copied out of their blobs like code, and count towards the same bound.
  std::vector<std::vector<uint32_t>> textureUsers(blobs.size());
  for (uint32_t t = 0; t < textures.size(); ++t) {
    totalCode += blobs[textures[t].blob].rawSize;
    if (totalCode > kMaxTotalCodeSize)
      return failure("shaders and textures up to texture '" + textures[t].name + "' hold more than " +
                     std::to_string(kMaxTotalCodeSize) + " bytes in total");
    textureUsers[textures[t].blob].push_back(t);
  }

  ReadResult result;
  Package pkg;
  pkg.compilerVersion = reader->compilerVersion();
  pkg.material = reader->material();
  pkg.mslBindings = reader->mslBindings();
  pkg.preshader = reader->preshader();
  pkg.variants.reserve(variants.size());
  result.stats.resize(variants.size());
  for (size_t v = 0; v < variants.size(); ++v) {
    pkg.variants.push_back(variantFromRow(variants[v]));
    for (const ShaderInfo& ref : variants[v].shaders) result.stats[v].push_back({blobs[ref.blob].rawSize, 0});
  }
  pkg.textures.reserve(textures.size());
  result.textureStats.resize(textures.size());
  for (size_t t = 0; t < textures.size(); ++t) {
    pkg.textures.push_back(textureFromRow(textures[t]));
    result.textureStats[t].rawSize = blobs[textures[t].blob].rawSize;
  }

  // Every blob is decoded, used or not (a dictionary is checked like code).
  for (uint32_t b = 0; b < blobs.size(); ++b) {
    std::optional<std::span<const uint8_t>> raw = reader->blob(b, &error);
    if (!raw) return failure(error);
    if (users[b].empty() && textureUsers[b].empty()) result.dictionaryStoredSize += blobs[b].storedSize;
    // The first user is charged the stored bytes, later users share them for free, so summing
    // storedSize over all shaders gives the blob bytes actually in the file.
    for (size_t u = 0; u < users[b].size(); ++u) {
      auto [v, s] = users[b][u];
      if (u == 0) result.stats[v][s].storedSize = blobs[b].storedSize;
      pkg.variants[v].shaders[s].code.assign(raw->begin(), raw->end());
    }
    for (size_t u = 0; u < textureUsers[b].size(); ++u) {
      uint32_t t = textureUsers[b][u];
      if (u == 0 && users[b].empty()) result.textureStats[t].storedSize = blobs[b].storedSize;
      pkg.textures[t].texels.assign(raw->begin(), raw->end());
    }
  }

  result.formatMajor = reader->formatMajor();
  result.formatMinor = reader->formatMinor();
  pkg.packedVertices = result.formatMinor >= kFirstMinorWithPackedVertices;
  pkg.instanceTransforms = result.formatMinor >= kFirstMinorWithInstanceTransforms;
  result.package = std::move(pkg);
  return result;
}

}  // namespace

ReadResult read(std::span<const uint8_t> bytes) {
  // Every size is checked before allocation, so this only fires on genuine memory exhaustion
  // within the documented limits; the contract is that no exception leaves read().
  try {
    return readChecked(bytes);
  } catch (const std::bad_alloc&) {
    return failure("out of memory while reading package (" + std::to_string(bytes.size()) + " bytes)");
  } catch (const std::exception& e) {
    return failure(std::string("internal error while reading package: ") + e.what());
  }
}

}  // namespace facet::package
