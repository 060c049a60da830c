#include "facet/ibl/dfg_lut.h"

#include <algorithm>
#include <cmath>

#include "facet/ibl/bilinear_axis.h"
#include "facet/ibl/ggx_microfacet.h"
#include "facet/ibl/hammersley.h"

namespace facet::ibl {
namespace {

double schlickWeight(double VoH) {
  double m = std::clamp(1.0 - VoH, 0.0, 1.0);
  double m2 = m * m;
  return m2 * m2 * m;
}

}  // namespace

DfgTerms integrateDfg(double NoV, double perceptualRoughness, int samples, DfgSampling sampling) {
  NoV = std::clamp(NoV, 1e-4, 1.0);
  double r = std::clamp(perceptualRoughness, 0.0, 1.0);
  double alpha = r * r;
  Vec3 v{std::sqrt(1.0 - NoV * NoV), 0.0, NoV};
  uint32_t n = static_cast<uint32_t>(std::max(samples, 1));
  double g1 = maskingSmithGgx(alpha, NoV);
  DfgTerms sum;
  for (uint32_t i = 0; i < n; ++i) {
    Point2 xi = hammersley(i, n);
    Vec3 h =
        sampling == DfgSampling::VisibleNormals ? sampleGgxVisibleNormal(xi, v, alpha) : sampleGgxNormal(xi, alpha);
    double VoH = dot(v, h);
    Vec3 l = reflectAbout(v, h);
    double NoL = l.z;
    if (NoL <= 0.0 || VoH <= 0.0) continue;
    // Estimator D V n·l / pdf(l), pdf(l) = pdf(h) / (4 v·h).
    //   VNDF:  pdf(h) = G1(v) v·h D / n·v  →  4 V n·l n·v / G1(v) = G2 / G1(v) ≤ 1
    //   D n·h: pdf(h) = D n·h               →  4 V n·l v·h / n·h
    double V = visibilitySmithGgxCorrelated(alpha, NoV, NoL);
    double weight = sampling == DfgSampling::VisibleNormals ? 4.0 * V * NoL * NoV / g1 : 4.0 * V * NoL * VoH / h.z;
    sum.albedo += weight;
    sum.fresnelWeighted += weight * schlickWeight(VoH);
  }
  return {sum.fresnelWeighted / n, sum.albedo / n};
}

DfgTerms DfgLut::at(int column, int row) const {
  size_t i = (size_t(row) * size_t(size) + size_t(column)) * 2;
  return {texels[i], texels[i + 1]};
}

DfgTerms DfgLut::sampleBilinear(double NoV, double perceptualRoughness) const {
  const BilinearAxis x = bilinearAxis(NoV, size), y = bilinearAxis(perceptualRoughness, size);
  auto lerp = [](DfgTerms a, DfgTerms b, double f) {
    return DfgTerms{a.fresnelWeighted + (b.fresnelWeighted - a.fresnelWeighted) * f,
                    a.albedo + (b.albedo - a.albedo) * f};
  };
  return lerp(lerp(at(x.i0, y.i0), at(x.i1, y.i0), x.t), lerp(at(x.i0, y.i1), at(x.i1, y.i1), x.t), y.t);
}

DfgLut generateDfgLut(int size, int samplesPerTexel) {
  DfgLut lut;
  lut.size = std::max(size, 1);
  lut.texels.resize(size_t(lut.size) * size_t(lut.size) * 2);
  for (int row = 0; row < lut.size; ++row) {
    double r = dfgLutRoughness(row, lut.size);
    for (int column = 0; column < lut.size; ++column) {
      DfgTerms t = integrateDfg(dfgLutNoV(column, lut.size), r, samplesPerTexel);
      size_t i = (size_t(row) * size_t(lut.size) + size_t(column)) * 2;
      lut.texels[i] = static_cast<float>(t.fresnelWeighted);
      lut.texels[i + 1] = static_cast<float>(t.albedo);
    }
  }
  return lut;
}

}  // namespace facet::ibl
