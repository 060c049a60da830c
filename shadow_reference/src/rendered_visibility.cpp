#include "facet/shadow_reference/rendered_visibility.h"

#include <cmath>
#include <limits>

#include "facet/runtime/image_texture.h"

namespace facet::shadow_reference {
namespace {

double decodeSrgb(uint8_t encoded) {
  const double c = encoded / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Rec. 709 luminance of an sRGB-encoded RGBA8 pixel.
double luminance(const uint8_t* rgba) {
  return 0.2126 * decodeSrgb(rgba[0]) + 0.7152 * decodeSrgb(rgba[1]) + 0.0722 * decodeSrgb(rgba[2]);
}

}  // namespace

std::optional<RenderedVisibility> visibilityFromImage(const std::string& path, std::string* error) {
  std::optional<runtime::Texture> image = runtime::loadImageTexture(path, false, error);
  if (!image) return std::nullopt;
  RenderedVisibility out{image->width, image->height, {}};
  const std::vector<uint8_t>& texels = image->levels.front();
  out.values.reserve(size_t(out.width) * out.height);
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i) out.values.push_back(float(texels[i * 4] / 255.0));
  return out;
}

std::optional<RenderedVisibility> visibilityFromFrames(const std::string& shadowedPath,
                                                       const std::string& unshadowedPath, std::string* error) {
  std::optional<runtime::Texture> shadowed = runtime::loadImageTexture(shadowedPath, false, error);
  if (!shadowed) return std::nullopt;
  std::optional<runtime::Texture> unshadowed = runtime::loadImageTexture(unshadowedPath, false, error);
  if (!unshadowed) return std::nullopt;
  if (shadowed->width != unshadowed->width || shadowed->height != unshadowed->height) {
    *error = unshadowedPath + ": " + std::to_string(unshadowed->width) + "x" + std::to_string(unshadowed->height) +
             ", but " + shadowedPath + " is " + std::to_string(shadowed->width) + "x" +
             std::to_string(shadowed->height);
    return std::nullopt;
  }
  RenderedVisibility out{shadowed->width, shadowed->height, {}};
  const uint8_t* lit = unshadowed->levels.front().data();
  const uint8_t* shaded = shadowed->levels.front().data();
  for (size_t i = 0; i < size_t(out.width) * out.height; ++i) {
    const double full = luminance(lit + 4 * i);
    out.values.push_back(full < kMeasurableLuminance ? std::numeric_limits<float>::quiet_NaN()
                                                     : float(luminance(shaded + 4 * i) / full));
  }
  return out;
}

}  // namespace facet::shadow_reference
