#include "facet/eval/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace facet::eval {

double psnr8(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  ErrorAccumulator acc;
  acc.add(a, b, {}, {});
  return acc.metrics().psnr;
}

void ErrorAccumulator::add(const std::vector<uint8_t>& ldr, const std::vector<uint8_t>& referenceLdr,
                           const std::vector<float>& hdr, const std::vector<float>& referenceHdr,
                           const std::vector<bool>& mask) {
  const size_t pixels = std::min(ldr.size(), referenceLdr.size()) / 4;
  const bool withHdr = hdr.size() >= pixels * 4 && referenceHdr.size() >= pixels * 4;
  for (size_t p = 0; p < pixels; ++p) {
    if (!mask.empty() && (p >= mask.size() || !mask[p])) continue;
    ++pixels_;
    for (size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int(ldr[4 * p + c]) - int(referenceLdr[4 * p + c]));
      ++histogram_[size_t(d)];
      sumAbs8_ += d;
      sumSq8_ += double(d) * d;
      if (!withHdr) continue;
      const double v = hdr[4 * p + c], r = referenceHdr[4 * p + c];
      if (!std::isfinite(v) || !std::isfinite(r)) {
        ++nonFinite_;
        continue;
      }
      sumSqDiffHdr_ += (v - r) * (v - r);
      sumSqReferenceHdr_ += r * r;
    }
  }
}

ImageMetrics ErrorAccumulator::metrics() const {
  ImageMetrics m;
  m.pixels = pixels_;
  m.nonFinite = nonFinite_;
  const double values = 3.0 * double(pixels_);
  if (values == 0) {
    m.psnr = std::numeric_limits<double>::infinity();
    m.identical = true;
    return m;
  }
  const double mse = sumSq8_ / values;
  m.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  m.meanAbs = sumAbs8_ / values;
  // The smallest step d with at least 99 % of the values at or below it; the largest step seen.
  const double target = 0.99 * values;
  uint64_t seen = 0;
  bool found = false;
  for (size_t d = 0; d < histogram_.size(); ++d) {
    seen += histogram_[d];
    if (histogram_[d] > 0) m.maxAbs = double(d);
    if (!found && double(seen) >= target) {
      m.p99Abs = double(d);
      found = true;
    }
  }
  m.relativeRmse = sumSqReferenceHdr_ > 0 ? std::sqrt(sumSqDiffHdr_ / sumSqReferenceHdr_) : 0.0;
  m.identical = mse == 0 && sumSqDiffHdr_ == 0 && nonFinite_ == 0;
  return m;
}

double ErrorAccumulator::psnrAtMost(size_t morePixels) const {
  if (sumSq8_ == 0) return std::numeric_limits<double>::infinity();
  const double mse = sumSq8_ / (3.0 * double(pixels_ + morePixels));
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

std::vector<bool> coverageMask(const std::vector<float>& hdr, const std::vector<float>& referenceHdr,
                               const std::array<float, 3>& background) {
  const size_t pixels = std::min(hdr.size(), referenceHdr.size()) / 4;
  std::vector<bool> mask(pixels, false);
  auto isBackground = [&](const std::vector<float>& image, size_t p) {
    for (size_t c = 0; c < 3; ++c) {
      const float v = image[4 * p + c], b = background[c];
      if (!(std::abs(v - b) <= 1e-3f * std::abs(b) + 1e-7f)) return false;
    }
    return true;
  };
  for (size_t p = 0; p < pixels; ++p) mask[p] = !isBackground(hdr, p) || !isBackground(referenceHdr, p);
  return mask;
}

double furnaceGain(const std::vector<float>& hdr, double radiance, const std::vector<bool>& mask) {
  double brightest = 0;
  for (size_t i = 0; i < hdr.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha
    if (!mask.empty() && (i / 4 >= mask.size() || !mask[i / 4])) continue;
    if (!std::isfinite(hdr[i])) return std::numeric_limits<double>::infinity();
    brightest = std::max(brightest, double(hdr[i]));
  }
  return brightest / radiance;
}

}  // namespace facet::eval
