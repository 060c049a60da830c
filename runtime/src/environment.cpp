#include "facet/runtime/environment.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>

#include "facet/abi/shader_abi.h"
#include "facet/ibl/cube_map.h"
#include "facet/ibl/dfg_lut.h"
#include "facet/ibl/embedded_dfg_lut.h"
#include "facet/ibl/equirect_image.h"
#include "facet/ibl/irradiance_cube.h"
#include "facet/ibl/prefilter_environment.h"
#include "facet/ibl/spherical_harmonics.h"
#include "facet/runtime/image_texture.h"

namespace facet::runtime {
namespace {

using ibl::EquirectImage;
using ibl::Vec3;

Vec3 toVec3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The analytic sky of docs/scene-format.md, relative (× luminance later). √|y| makes the colour
// change fast near the horizon, as a real sky's does, and keeps it continuous there.
Vec3 skyRadiance(const Environment& e, Vec3 d) {
  double y = std::clamp(d.y, -1.0, 1.0);
  const glm::dvec3& far = y >= 0 ? e.zenith : e.ground;
  double w = std::sqrt(std::abs(y));
  return toVec3(e.horizon * (1 - w) + far * w);
}

// Brings an equirect image to kEnvironmentWidth × kEnvironmentHeight: halving by solid-angle-
// weighted means while it is at least twice as large (no energy moves between latitudes), then
// bilinear resampling for what remains (a non-power-of-two or a smaller source).
EquirectImage fitEnvironment(EquirectImage image) {
  while (image.height >= 2 * kEnvironmentHeight && image.height % 2 == 0) image = ibl::downsampleEquirect(image);
  if (image.width == kEnvironmentWidth && image.height == kEnvironmentHeight) return image;
  EquirectImage out(kEnvironmentWidth, kEnvironmentHeight);
  for (int row = 0; row < out.height; ++row)
    for (int column = 0; column < out.width; ++column)
      out.setTexel(column, row, ibl::sampleBilinear(image, (column + 0.5) / out.width, (row + 0.5) / out.height));
  return out;
}

void storeLevels(const std::vector<ibl::CubeImage>& levels, double scale, EnvironmentLighting* out) {
  out->width = out->height = uint32_t(levels.at(0).size);
  out->levels.clear();
  for (const ibl::CubeImage& level : levels) {
    std::vector<float> rgb(level.rgb.size());
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(level.rgb[i] * scale);
    out->levels.push_back(std::move(rgb));
  }
}

// An analytic sky's SH, mean and prefiltered levels before the luminance scale: a function of its
// three colours alone, so the last few are kept. `matc eval` and `matc tune` prepare a frame per
// view and configuration of the same sky, and the prefilter (a few hundred milliseconds) was most
// of each configuration's time.
struct PrefilteredSky {
  glm::dvec3 zenith, horizon, ground;
  ibl::SphericalHarmonics radianceSh;
  Vec3 mean;
  std::vector<ibl::CubeImage> levels;
};

std::shared_ptr<const PrefilteredSky> prefilteredSky(const Environment& e) {
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const PrefilteredSky>> kept;  // most recent last
  constexpr size_t kKept = 4;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& s : kept)
      if (s->zenith == e.zenith && s->horizon == e.horizon && s->ground == e.ground) return s;
  }
  auto sky = [&](Vec3 d) { return skyRadiance(e, d); };
  auto made = std::make_shared<PrefilteredSky>();
  made->zenith = e.zenith;
  made->horizon = e.horizon;
  made->ground = e.ground;
  const EquirectImage source = ibl::renderEquirect(kEnvironmentWidth, kEnvironmentHeight, sky);
  // The analytic sky is projected by quadrature of the function itself, not of its 128 × 64 image.
  made->radianceSh = ibl::projectRadiance(std::function<Vec3(Vec3)>(sky), ibl::kMaxShBands);
  made->mean = ibl::meanRadiance(source);
  ibl::PrefilterOptions options;
  options.levels = int(abi::kEnvironmentLevels);
  made->levels = ibl::prefilterEnvironmentCube(source, kEnvironmentMapSize, options);
  std::lock_guard<std::mutex> lock(mutex);
  kept.push_back(made);
  if (kept.size() > kKept) kept.erase(kept.begin());
  return made;
}

// RGB floats as RGBA16F texels (alpha 1), little-endian (render_backend.h).
std::vector<uint8_t> rgba16Texels(const std::vector<float>& rgb) {
  std::vector<uint8_t> bytes(rgb.size() / 3 * 8);
  for (size_t i = 0; i < rgb.size() / 3; ++i) {
    const uint16_t texel[4] = {floatToHalf(rgb[3 * i]), floatToHalf(rgb[3 * i + 1]), floatToHalf(rgb[3 * i + 2]),
                               floatToHalf(1.0f)};
    for (size_t ch = 0; ch < 4; ++ch) {
      bytes[8 * i + 2 * ch] = uint8_t(texel[ch] & 0xff);
      bytes[8 * i + 2 * ch + 1] = uint8_t(texel[ch] >> 8);
    }
  }
  return bytes;
}

}  // namespace

uint16_t floatToHalf(float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  const uint16_t sign = uint16_t((bits >> 16) & 0x8000u);
  const uint32_t magnitude = bits & 0x7fffffffu;
  if (magnitude > 0x7f800000u) return uint16_t(sign | 0x7e00u);   // NaN stays NaN
  if (magnitude >= 0x477ff000u) return uint16_t(sign | 0x7bffu);  // rounds to ≥ 65520: saturate at 65504
  if (magnitude < 0x38800000u) {                                  // below 2^-14: a subnormal half (or 0)
    if (magnitude < 0x33000000u) return sign;                     // below half of the smallest subnormal
    uint32_t mantissa = (magnitude & 0x7fffffu) | 0x800000u;
    // value = mantissa · 2^(e − 150) = k · 2^-24 with k = mantissa >> (126 − e), e the biased exponent
    int shift = 126 - int(magnitude >> 23);
    uint32_t halfMantissa = mantissa >> shift;
    uint32_t rest = mantissa & ((1u << shift) - 1);
    uint32_t halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (halfMantissa & 1u))) ++halfMantissa;
    return uint16_t(sign | halfMantissa);
  }
  uint32_t h = ((magnitude - 0x38000000u) >> 13);  // rebias exponent 127 → 15, keep 10 mantissa bits
  uint32_t rest = magnitude & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;  // carries into the exponent correctly
  return uint16_t(sign | h);
}

std::optional<EnvironmentLighting> buildEnvironmentLighting(const Scene& scene, double exposure, std::string* error) {
  EnvironmentLighting out;
  if (!scene.environment) {
    // A constant sky L: irradiance is π L for every normal, so irradiance / π = L is the whole SH
    // (band 0), and prefiltering a constant changes nothing: every level is L, no sampling error.
    // The faces are as small as the level count allows (1² at the last level).
    const float l = float(scene.skyLuminance * exposure);
    for (int c = 0; c < 3; ++c) out.sh[0][size_t(c)] = out.meanRadiance[size_t(c)] = l;
    out.width = out.height = 1u << (abi::kEnvironmentLevels - 1);
    for (uint32_t m = 0; m < abi::kEnvironmentLevels; ++m)
      out.levels.emplace_back(size_t(ibl::kCubeFaces) * (out.width >> m) * (out.height >> m) * 3, l);
    return out;
  }
  const Environment& e = *scene.environment;
  const double scale = e.luminance * exposure;
  EquirectImage source;
  ibl::SphericalHarmonics radianceSh;
  std::shared_ptr<const PrefilteredSky> sky;
  if (e.image.empty()) {
    sky = prefilteredSky(e);
    radianceSh = sky->radianceSh;
  } else {
    std::vector<uint8_t> bytes;
    if (!readImageFile(e.image, &bytes, error)) return std::nullopt;
    auto image = decodeEquirectImage(bytes, e.image, error);
    if (!image) return std::nullopt;
    source = fitEnvironment(std::move(*image));
    radianceSh = ibl::projectRadiance(source, ibl::kMaxShBands);
  }
  // SH3's nine, then band 4's (k = 16..24) for the variants that read it; band 3's are zero.
  constexpr size_t kBand4First = 16;  // l² for l = 4
  std::vector<Vec3> c = ibl::shaderIrradianceCoefficients(radianceSh);
  for (size_t k = 0; k < out.sh.size(); ++k) {
    const Vec3& ck = c[k < abi::kShCoefficients ? k : k - abi::kShCoefficients + kBand4First];
    out.sh[k] = {float(ck.x * scale), float(ck.y * scale), float(ck.z * scale)};
  }
  Vec3 mean = sky ? sky->mean : ibl::meanRadiance(source);
  out.meanRadiance = {float(mean.x * scale), float(mean.y * scale), float(mean.z * scale)};
  if (sky) {
    storeLevels(sky->levels, scale, &out);
    return out;
  }
  ibl::PrefilterOptions options;
  options.levels = int(abi::kEnvironmentLevels);
  storeLevels(ibl::prefilterEnvironmentCube(source, kEnvironmentMapSize, options), scale, &out);
  return out;
}

Texture environmentTexture(const EnvironmentLighting& lighting) {
  Texture t;
  t.width = lighting.width;
  t.height = lighting.height;
  t.format = TextureFormat::Rgba16Float;
  t.linearFilter = true;
  t.cube = true;  // filtered across faces by both backends (chunks/environment_cube.glsl)
  for (const std::vector<float>& rgb : lighting.levels) t.levels.push_back(rgba16Texels(rgb));
  return t;
}

Texture irradianceTexture(const EnvironmentLighting& lighting) {
  std::vector<Vec3> sh3(abi::kShCoefficients);
  for (size_t k = 0; k < sh3.size(); ++k) sh3[k] = {lighting.sh[k][0], lighting.sh[k][1], lighting.sh[k][2]};
  const ibl::CubeImage cube = ibl::tabulateIrradiance(sh3, int(abi::kIrradianceMapSize));
  Texture t;
  t.width = t.height = abi::kIrradianceMapSize;
  t.format = TextureFormat::Rgba16Float;
  t.linearFilter = true;
  t.cube = true;
  std::vector<float> rgb(cube.rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = float(cube.rgb[i]);
  t.levels.push_back(rgba16Texels(rgb));
  return t;
}

void setEnvironment(FrameDesc& frame, const EnvironmentLighting& lighting, const Texture& environment,
                    const Texture& irradiance) {
  for (size_t k = 0; k < abi::kShFrameCoefficients; ++k)
    for (size_t c = 0; c < 3; ++c) frame.frame.sh[k][c] = lighting.sh[k][c];
  for (size_t c = 0; c < 3; ++c) frame.clearColor[c] = lighting.meanRadiance[c];
  frame.frameTextures.push_back({abi::kEnvironmentBinding, abi::kEnvironmentName, &environment});
  frame.frameTextures.push_back({abi::kIrradianceBinding, abi::kIrradianceName, &irradiance});
  frame.frameTextures.push_back({abi::kDfgLutBinding, abi::kDfgLutName, &dfgTexture()});
}

const DfgTable& dfgTable() { return ibl::embeddedDfgLut(); }

const Texture& dfgTexture() {
  static const Texture texture = [] {
    const DfgTable& table = dfgTable();
    const ibl::SheenLut& sheen = ibl::embeddedSheenLut();
    Texture t;
    t.width = t.height = uint32_t(table.size);
    // The sheen in the same texture, not a table of its own: a material with a sheen layer over
    // the standard model reads all four channels in one fetch (docs/material-models.md, "Cloth").
    t.format = TextureFormat::Rgba16Float;
    t.linearFilter = true;
    t.repeat = false;
    const size_t count = size_t(table.size) * size_t(table.size);
    std::vector<uint8_t> bytes(count * 8);
    for (size_t i = 0; i < count; ++i) {
      const ibl::SheenTerms s = ibl::sheenTexelTerms(sheen, int(i % size_t(table.size)), int(i / size_t(table.size)));
      const float rgba[4] = {table.texels[2 * i], table.texels[2 * i + 1], float(s.albedo), float(s.scale)};
      for (size_t c = 0; c < 4; ++c) {
        uint16_t h = floatToHalf(rgba[c]);
        bytes[8 * i + 2 * c] = uint8_t(h & 0xff);
        bytes[8 * i + 2 * c + 1] = uint8_t(h >> 8);
      }
    }
    t.levels.push_back(std::move(bytes));
    return t;
  }();
  return texture;
}

}  // namespace facet::runtime
