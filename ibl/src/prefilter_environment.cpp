#include "facet/ibl/prefilter_environment.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "facet/ibl/ggx_microfacet.h"
#include "facet/ibl/hammersley.h"

namespace facet::ibl {
namespace {

// Bilinear reconstruction on an equirect grid of very few rows moves energy between latitudes
// (with 2 or 4 rows the north and south halves blend at the equator). In development runs on the
// cap sky of docs/ibl.md, reading mips down to 1 row put the mean of the rough levels 1–3 % (lod
// bias 0) to 5 % (lod bias 1) above the source's; stopping at 8 rows kept it within 1 %.
constexpr int kCoarsestSourceRows = 8;

// One GGX sample in the tangent frame of n = v: the reflected direction and the part of its
// source lod that does not depend on where it lands.
struct LobeSample {
  Vec3 l;                  // tangent space, l.z = n·l > 0
  double lodWithoutTexel;  // ½ log2(Ω_sample) + lodBias; −∞-like for the mirror, clamped to 0
};

std::vector<LobeSample> lobeSamples(double alpha, int count, double lodBias) {
  std::vector<LobeSample> lobe;
  uint32_t n = static_cast<uint32_t>(std::max(count, 1));
  if (alpha == 0.0) return {{{0.0, 0.0, 1.0}, -1e30}};  // a mirror: every sample is n itself
  for (uint32_t i = 0; i < n; ++i) {
    Vec3 h = sampleGgxNormal(hammersley(i, n), alpha);
    Vec3 l = reflectAbout({0.0, 0.0, 1.0}, h);
    if (l.z <= 0.0) continue;
    // pdf(l) = D n·h / (4 v·h) = D / 4 since v = n.
    double pdf = distributionGgx(alpha, h.z) / 4.0;
    lobe.push_back({l, 0.5 * std::log2(1.0 / (n * pdf)) + lodBias});
  }
  return lobe;
}

Vec3 sampleTrilinear(const std::vector<EquirectImage>& mips, double s, double t, double lod) {
  lod = std::clamp(lod, 0.0, double(mips.size() - 1));
  int lower = static_cast<int>(lod);
  int upper = std::min(lower + 1, int(mips.size()) - 1);
  double f = lod - lower;
  Vec3 a = sampleBilinear(mips[size_t(lower)], s, t);
  if (f == 0.0 || upper == lower) return a;
  return a * (1.0 - f) + sampleBilinear(mips[size_t(upper)], s, t) * f;
}

// The lobe average around direction n, read from the source mips (see the header).
Vec3 prefilterTexel(const std::vector<EquirectImage>& sourceMips, const std::vector<LobeSample>& lobe, Vec3 n) {
  const EquirectImage& source = sourceMips[0];
  TangentFrame frame(n);
  Vec3 sum;
  double weightSum = 0.0;
  for (const LobeSample& sample : lobe) {
    Vec3 l = frame.toWorld(sample.l);
    double s, t;
    equirectCoordinates(l, &s, &t);
    int sourceRow = std::clamp(static_cast<int>(t * source.height), 0, source.height - 1);
    double lod = sample.lodWithoutTexel - 0.5 * std::log2(equirectTexelSolidAngle(source, sourceRow));
    sum += sampleTrilinear(sourceMips, s, t, lod) * sample.l.z;
    weightSum += sample.l.z;
  }
  return sum * (1.0 / weightSum);
}

EquirectImage prefilterLevel(const std::vector<EquirectImage>& sourceMips, int width, int height, double alpha,
                             const PrefilterOptions& options) {
  std::vector<LobeSample> lobe = lobeSamples(alpha, options.samples, options.lodBias);
  EquirectImage out(width, height);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      out.setTexel(column, row, prefilterTexel(sourceMips, lobe, equirectDirection(out, column, row)));
  return out;
}

// Every level's texels are independent, so rows of every face of every level are shared out
// to the threads; each texel is computed by the same code whichever thread takes it, so the
// result does not depend on the thread count (CubeMap.PrefilteredLevelsDoNotDependOnTheThreadCount).
std::vector<CubeImage> prefilterCubeLevels(const std::vector<EquirectImage>& sourceMips, int size, int levels,
                                           const PrefilterOptions& options) {
  struct Level {
    std::vector<LobeSample> lobe;
    CubeImage image;
  };
  std::vector<Level> out;
  struct Row {
    int level, face, row;
  };
  std::vector<Row> rows;
  for (int m = 0; m < levels; ++m) {
    const double r = prefilterLevelRoughness(m, levels);
    out.push_back({lobeSamples(r * r, options.samples, options.lodBias), CubeImage(size >> m)});
    for (int face = 0; face < kCubeFaces; ++face)
      for (int row = 0; row < size >> m; ++row) rows.push_back({m, face, row});
  }
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < rows.size(); i = next++) {
      Level& level = out[size_t(rows[i].level)];
      for (int column = 0; column < level.image.size; ++column)
        level.image.setTexel(rows[i].face, column, rows[i].row,
                             prefilterTexel(sourceMips, level.lobe,
                                            cubeTexelDirection(level.image.size, rows[i].face, column, rows[i].row)));
    }
  };
  const unsigned threads =
      options.threads > 0 ? unsigned(options.threads) : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> helpers;
  try {
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
  } catch (const std::system_error&) {
    // No more threads to be had (a sandbox, a thread limit): the ones started and this one
    // share the rows all the same.
  }
  work();
  for (std::thread& t : helpers) t.join();
  std::vector<CubeImage> result;
  for (Level& level : out) result.push_back(std::move(level.image));
  return result;
}

void checkSource(const EquirectImage& source, int levels) {
  if (levels < 1 || levels > 30 || source.height < 1 || source.width != 2 * source.height ||
      source.height % (1 << (levels - 1)) != 0 || source.rgb.size() != size_t(source.width) * size_t(source.height) * 3)
    throw std::invalid_argument(
        "prefilterEnvironment: source must be 2h x h floats with h divisible by 2^(levels - 1)");
}

// Source mips for filtered sampling, halving while the result keeps kCoarsestSourceRows rows.
std::vector<EquirectImage> sourceMipChain(const EquirectImage& source) {
  std::vector<EquirectImage> sourceMips{source};
  while (sourceMips.back().height % 2 == 0 && sourceMips.back().height / 2 >= kCoarsestSourceRows)
    sourceMips.push_back(downsampleEquirect(sourceMips.back()));
  return sourceMips;
}

}  // namespace

double prefilterLevelRoughness(int level, int levels) {
  if (levels <= 1) return 0.0;
  // The inverse of the shader's lod = (levels − 1) · r (2 − r) (chunks/ibl_prefiltered.glsl).
  return 1.0 - std::sqrt(1.0 - double(level) / double(levels - 1));
}

std::vector<EquirectImage> prefilterEnvironment(const EquirectImage& source, const PrefilterOptions& options) {
  const int levels = options.levels;
  checkSource(source, levels);
  const std::vector<EquirectImage> sourceMips = sourceMipChain(source);
  std::vector<EquirectImage> result;
  for (int m = 0; m < levels; ++m) {
    double r = prefilterLevelRoughness(m, levels);
    result.push_back(prefilterLevel(sourceMips, source.width >> m, source.height >> m, r * r, options));
  }
  return result;
}

std::vector<CubeImage> prefilterEnvironmentCube(const EquirectImage& source, int size,
                                                const PrefilterOptions& options) {
  const int levels = options.levels;
  checkSource(source, levels);
  if (size < 1 << (levels - 1) || size % (1 << (levels - 1)) != 0)
    throw std::invalid_argument("prefilterEnvironmentCube: size must be divisible by 2^(levels - 1)");
  return prefilterCubeLevels(sourceMipChain(source), size, levels, options);
}

}  // namespace facet::ibl
