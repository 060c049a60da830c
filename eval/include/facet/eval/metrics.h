// Image error metrics of `matc eval` and the tests: a rendered image against a reference image of
// the same scene (docs/eval.md, "What is measured"). No dependency beyond the standard library,
// so tests link it on its own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet::eval {

// 8-bit PSNR over the RGB values of two RGBA8 images of the same size: 10·log10(255² / MSE).
// +infinity when they are identical (and when both are empty).
double psnr8(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

struct ImageMetrics {
  double psnr = 0;     // dB, tone-mapped 8-bit RGB; +infinity when identical
  double meanAbs = 0;  // mean |difference| of the 8-bit RGB values, in 8-bit steps
  double p99Abs = 0;   // 99th percentile of the same (an integer number of steps)
  double maxAbs = 0;
  double relativeRmse = 0;  // linear HDR RGB: sqrt(Σ (image − reference)² / Σ reference²)
  size_t pixels = 0;        // pixels compared
  size_t nonFinite = 0;     // HDR values that are NaN or infinite (left out of relativeRmse)
  bool identical = false;   // 8-bit and HDR values equal on every compared pixel
};

// Accumulates the error of image against reference over one or more image pairs (e.g. the views of
// a scene), then reports it as one set of metrics. Images are RGBA8 (post pass) and RGBA float
// (HDR), rows in the same order, of the same size within a pair.
class ErrorAccumulator {
 public:
  // mask: the pixels to compare (empty: all). coverageMask below gives the pixels a material covers.
  void add(const std::vector<uint8_t>& ldr, const std::vector<uint8_t>& referenceLdr, const std::vector<float>& hdr,
           const std::vector<float>& referenceHdr, const std::vector<bool>& mask = {});
  ImageMetrics metrics() const;
  // The highest PSNR metrics() can report once at most `morePixels` more pixels are added: their
  // squared error is at least 0, so the mean squared error is at least the sum so far over all the
  // values. Both are the same rounded operations on a sum that only grows and a count that only
  // shrinks, so metrics().psnr never exceeds it, however the pixels turn out.
  double psnrAtMost(size_t morePixels) const;

 private:
  std::array<uint64_t, 256> histogram_{};  // |difference| of 8-bit values
  double sumSq8_ = 0;
  double sumAbs8_ = 0;
  double sumSqDiffHdr_ = 0;
  double sumSqReferenceHdr_ = 0;
  size_t pixels_ = 0;
  size_t nonFinite_ = 0;
};

// The pixels where either HDR image differs from the background value (the clear colour, as the
// RGBA16F target stores it: equal within 1e-3 relative): the pixels geometry covers in either.
std::vector<bool> coverageMask(const std::vector<float>& hdr, const std::vector<float>& referenceHdr,
                               const std::array<float, 3>& background);

// The white furnace (docs/eval.md): in a constant environment of radiance L, no surface may
// reflect more than L (energy conservation; a white metal with multiple-scattering compensation
// reflects exactly L). Returns the brightest RGB value of an RGBA float image over the masked
// pixels (empty mask: all) divided by L (pre-exposed, as the image), +inf if such a value is not
// finite, 0 when no pixel is masked.
double furnaceGain(const std::vector<float>& hdr, double radiance, const std::vector<bool>& mask = {});

}  // namespace facet::eval
