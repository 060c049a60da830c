#include "rows.h"

namespace facet::package::detail {

VariantInfo variantRow(const Variant& variant, const std::function<uint32_t(const Shader&)>& blobOf) {
  VariantInfo row{variant.key, {}};
  row.shaders.reserve(variant.shaders.size());
  for (const Shader& s : variant.shaders) row.shaders.push_back({s.stage, s.target, blobOf(s)});
  return row;
}

TextureInfo textureRow(const Texture& texture, uint32_t blob) {
  return {texture.name, texture.width, texture.height, texture.format, blob, texture.variants};
}

Variant variantFromRow(const VariantInfo& row) {
  Variant variant{row.key, {}};
  variant.shaders.reserve(row.shaders.size());
  for (const ShaderInfo& s : row.shaders) variant.shaders.push_back({s.stage, s.target, {}});
  return variant;
}

Texture textureFromRow(const TextureInfo& row) {
  return {row.name, row.width, row.height, row.format, {}, row.variants};
}

}  // namespace facet::package::detail
