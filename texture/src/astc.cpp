#include "facet/texture/astc.h"

#include <astcenc.h>

#include <memory>

namespace facet::texture {
namespace {

struct ContextFree {
  void operator()(astcenc_context* context) const { astcenc_context_free(context); }
};
using Context = std::unique_ptr<astcenc_context, ContextFree>;

uint64_t blockBytes(uint32_t width, uint32_t height, uint32_t blockWidth, uint32_t blockHeight) {
  return uint64_t((width + blockWidth - 1) / blockWidth) * ((height + blockHeight - 1) / blockHeight) * 16;
}

Context makeContext(astcenc_profile profile, uint32_t blockWidth, uint32_t blockHeight, float quality, unsigned flags,
                    TextureUsage usage, unsigned threads, std::string* error) {
  astcenc_config config{};
  astcenc_error status = astcenc_config_init(profile, blockWidth, blockHeight, 1, quality, flags, &config);
  if (status == ASTCENC_SUCCESS && usage == TextureUsage::Normal) config.cw_a_weight = 0.0f;  // alpha is set to 1
  astcenc_context* context = nullptr;
  if (status == ASTCENC_SUCCESS) status = astcenc_context_alloc(&config, threads, &context);
  if (status != ASTCENC_SUCCESS) {
    *error = std::string("astcenc: ") + astcenc_get_error_string(status);
    return nullptr;
  }
  return Context(context);
}

}  // namespace

std::optional<std::vector<uint8_t>> encodeAstc(std::span<const uint8_t> rgba, uint32_t width, uint32_t height,
                                               const AstcSettings& settings, std::string* error) {
  if (rgba.size() != uint64_t(width) * height * 4) {
    *error = "astcenc: " + std::to_string(rgba.size()) + " bytes are not a " + std::to_string(width) + "x" +
             std::to_string(height) + " RGBA8 image";
    return std::nullopt;
  }
  const astcenc_profile profile = settings.usage == TextureUsage::Color ? ASTCENC_PRF_LDR_SRGB : ASTCENC_PRF_LDR;
  // astcenc's normal-map mode (ASTCENC_FLG_MAP_NORMAL) encodes x and y only, for a shader that
  // rebuilds z; Facet's shaders read all three (ir/src/emit_glsl.cpp, `sample_normal`), so a normal
  // map is encoded as three linear channels, with alpha forced to 1 so that no bits go to it.
  Context context = makeContext(profile, settings.blockWidth, settings.blockHeight, settings.quality, 0, settings.usage,
                                settings.threads, error);
  if (!context) return std::nullopt;
  const astcenc_swizzle swizzle = settings.usage == TextureUsage::Normal
                                      ? astcenc_swizzle{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_1}
                                      : astcenc_swizzle{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};
  void* slice = const_cast<uint8_t*>(rgba.data());  // astcenc reads the input only
  astcenc_image image{width, height, 1, ASTCENC_TYPE_U8, &slice};
  std::vector<uint8_t> blocks(blockBytes(width, height, settings.blockWidth, settings.blockHeight));
  const astcenc_error status = astcenc_compress_image(context.get(), &image, &swizzle, blocks.data(), blocks.size(), 0);
  if (status != ASTCENC_SUCCESS) {
    *error = std::string("astcenc: ") + astcenc_get_error_string(status);
    return std::nullopt;
  }
  return blocks;
}

std::optional<std::vector<uint8_t>> decodeAstc(std::span<const uint8_t> blocks, uint32_t width, uint32_t height,
                                               uint32_t blockWidth, uint32_t blockHeight, bool srgb,
                                               std::string* error) {
  if (blocks.size() != blockBytes(width, height, blockWidth, blockHeight)) {
    *error = "astcenc: " + std::to_string(blocks.size()) + " bytes are not the " + std::to_string(blockWidth) + "x" +
             std::to_string(blockHeight) + " blocks of a " + std::to_string(width) + "x" + std::to_string(height) +
             " image";
    return std::nullopt;
  }
  Context context = makeContext(srgb ? ASTCENC_PRF_LDR_SRGB : ASTCENC_PRF_LDR, blockWidth, blockHeight, 0.0f,
                                ASTCENC_FLG_DECOMPRESS_ONLY, TextureUsage::Data, 1, error);
  if (!context) return std::nullopt;
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  void* slice = rgba.data();
  astcenc_image image{width, height, 1, ASTCENC_TYPE_U8, &slice};
  const astcenc_swizzle identity{ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};
  const astcenc_error status =
      astcenc_decompress_image(context.get(), blocks.data(), blocks.size(), &image, &identity, 0);
  if (status != ASTCENC_SUCCESS) {
    *error = std::string("astcenc: ") + astcenc_get_error_string(status);
    return std::nullopt;
  }
  return rgba;
}

}  // namespace facet::texture
