#include "facet/ibl/sphere_quadrature.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {
namespace {

struct Node {
  double x, w;
};

// P_n(x) and its derivative, by the three-term recurrence.
struct Legendre {
  double p, dp;
};
Legendre legendre(int n, double x) {
  double p0 = 1.0, p1 = x;
  for (int k = 2; k <= n; ++k) {
    double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  return {p1, n * (x * p1 - p0) / (x * x - 1.0)};
}

// Roots of P_n by Newton's method from Tricomi's estimate, and the weights
// 2 / ((1 − x²) P_n'(x)²) (Abramowitz & Stegun 25.4.29).
std::vector<Node> gaussLegendre(int n) {
  std::vector<Node> nodes(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    for (int iteration = 0; iteration < 100; ++iteration) {
      Legendre l = legendre(n, x);
      double step = l.p / l.dp;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    double dp = legendre(n, x).dp;
    nodes[size_t(i)] = {x, 2.0 / ((1.0 - x * x) * dp * dp)};
  }
  return nodes;
}

}  // namespace

std::vector<SphereSample> sphereQuadrature(int order) {
  int n = std::max(order, 1);
  int azimuths = 2 * n;
  std::vector<SphereSample> samples;
  samples.reserve(size_t(n) * size_t(azimuths));
  for (const Node& node : gaussLegendre(n)) {
    double sinTheta = std::sqrt(std::max(0.0, 1.0 - node.x * node.x));
    for (int j = 0; j < azimuths; ++j) {
      double phi = 2.0 * kPi * (j + 0.5) / azimuths;
      samples.push_back({{sinTheta * std::cos(phi), sinTheta * std::sin(phi), node.x}, node.w * 2.0 * kPi / azimuths});
    }
  }
  return samples;
}

}  // namespace facet::ibl
