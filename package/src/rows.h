// The one place the package model (package.h: shaders with their code, textures with their
// texels) and its table rows (package_reader.h: ShaderInfo, VariantInfo, TextureInfo, which
// sections VARS and TEXS store, code and texels by blob index) are converted into each other.
// A field added to a row or to the model is carried here, and tests/package/test_package.cpp's round
// trip (Package.RowsRoundTripEverySection) sets it.
#pragma once

#include <cstdint>
#include <functional>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"

namespace facet::package::detail {

// Model -> rows: `blobOf` gives the blob index of a shader's code or a texture's texels.
VariantInfo variantRow(const Variant& variant, const std::function<uint32_t(const Shader&)>& blobOf);
TextureInfo textureRow(const Texture& texture, uint32_t blob);

// Rows -> model, without the bytes: the shaders' code and the texels are the blobs' (the caller
// decodes them).
Variant variantFromRow(const VariantInfo& row);
Texture textureFromRow(const TextureInfo& row);

}  // namespace facet::package::detail
