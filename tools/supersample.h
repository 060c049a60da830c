// tools/supersample.h — the supersampled references and camera sweeps of tools/measure_msaa.cpp
// and tools/measure_specular_aa.cpp (and the test that bounds the latter's figures): a scene
// rendered at `scale`× its width and height with one sample, each scale×scale block averaged, and
// the camera moved sideways by a fraction of a pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"

namespace facet::supersample {

inline double decode(double encoded) {
  const double c = encoded / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// chunks/srgb.glsl, then the UNORM target's rounding.
inline uint8_t encode(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double e = c < 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return uint8_t(std::lround(e * 255.0));
}

// chunks/tonemap_aces.glsl (Narkowicz's fit).
inline double aces(double x) {
  x = std::clamp(x, 0.0, 160.0);
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// The scene at scale× its size, the camera and its target moved sideways by shiftPixels pixels
// (of the unscaled image) at the target's distance.
inline bool render(runtime::RenderBackend& backend, runtime::Scene scene, uint32_t scale, double shiftPixels,
                   const std::string& packages, runtime::FrameResult* out, std::string* error) {
  const runtime::Camera& c = scene.camera;
  const glm::dvec3 forward = c.target - c.position;
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const double pixel = 2.0 * glm::length(forward) * std::tan(glm::radians(c.fovYDegrees) / 2) / scene.height;
  scene.camera.position += right * shiftPixels * pixel;
  scene.camera.target += right * shiftPixels * pixel;
  scene.width *= scale;
  scene.height *= scale;
  auto frame = runtime::SceneFrame::prepare(scene, packages, error);
  return frame && backend.render(frame->frame(), out, error);
}

// Each `scale`×`scale` block's values of one channel, read by value(index into the big image's
// RGBA values), averaged, and written by finish(mean).
template <typename Value, typename Finish>
std::vector<uint8_t> downsample(const runtime::FrameResult& big, uint32_t scale, Value value, Finish finish) {
  const uint32_t w = big.width / scale, h = big.height / scale;
  std::vector<uint8_t> out(size_t{w} * h * 4, 255);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        double sum = 0;
        for (uint32_t j = 0; j < scale; ++j)
          for (uint32_t i = 0; i < scale; ++i)
            sum += value(((size_t{y} * scale + j) * big.width + x * scale + i) * 4 + ch);
        out[(size_t{y} * w + x) * 4 + ch] = finish(sum / (scale * scale));
      }
  return out;
}

// The 8-bit output averaged in linear light.
inline std::vector<uint8_t> downsampleLdr(const runtime::FrameResult& big, uint32_t scale) {
  return downsample(
      big, scale, [&](size_t i) { return decode(big.ldr[i]); }, encode);
}

// The HDR samples averaged, then tone-mapped and encoded (resolve first).
inline std::vector<uint8_t> resolveThenToneMap(const runtime::FrameResult& big, uint32_t scale) {
  return downsample(
      big, scale, [&](size_t i) { return double(big.hdr[i]); }, [](double mean) { return encode(aces(mean)); });
}

// Mean |a − b| over the RGB values of two RGBA8 images.
inline double meanAbsDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (i % 4 == 3) continue;
    sum += std::abs(int(a[i]) - int(b[i]));
    ++n;
  }
  return sum / double(n);
}

// Mean over consecutive frames of the mean |frame k+1 − frame k|, and of the mean |that change −
// the reference's|.
inline void flicker(const std::vector<std::vector<uint8_t>>& frames, const std::vector<std::vector<uint8_t>>& truth,
                    double* change, double* excess) {
  *change = *excess = 0;
  for (size_t k = 0; k + 1 < frames.size(); ++k) {
    *change += meanAbsDifference(frames[k + 1], frames[k]);
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < frames[k].size(); ++i) {
      if (i % 4 == 3) continue;
      const int d = int(frames[k + 1][i]) - int(frames[k][i]);
      const int t = int(truth[k + 1][i]) - int(truth[k][i]);
      sum += std::abs(d - t);
      ++n;
    }
    *excess += sum / double(n);
  }
  *change /= double(frames.size() - 1);
  *excess /= double(frames.size() - 1);
}

}  // namespace facet::supersample
