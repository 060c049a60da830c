#include "facet/ibl/ggx_microfacet.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {

double distributionGgx(double alpha, double NoH) {
  double a2 = alpha * alpha;
  double d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

double visibilitySmithGgxCorrelated(double alpha, double NoV, double NoL) {
  double a2 = alpha * alpha;
  double lambdaV = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
  double lambdaL = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
  return 0.5 / (lambdaV + lambdaL);
}

double maskingSmithGgx(double alpha, double NoV) {
  double a2 = alpha * alpha;
  return 2.0 * NoV / (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV));
}

Vec3 sampleGgxNormal(Point2 xi, double alpha) {
  double a2 = alpha * alpha;
  double phi = 2.0 * kPi * xi.v;
  // Inverse CDF of D(h) n·h in cos²θ_h (Walter et al. 2007, eq. 35, written without tan).
  double cos2 = (1.0 - xi.u) / (1.0 + (a2 - 1.0) * xi.u);
  double cosTheta = std::sqrt(cos2);
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - cos2));
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Vec3 sampleGgxVisibleNormal(Point2 xi, Vec3 v, double alpha) {
  // Heitz 2018, listing 1: stretch v to the hemisphere configuration (α = 1), sample the
  // projected disk, warp it to the visible half, unstretch.
  Vec3 vh = normalize(Vec3{alpha * v.x, alpha * v.y, v.z});
  double lensq = vh.x * vh.x + vh.y * vh.y;
  Vec3 t1 = lensq > 0.0 ? Vec3{-vh.y, vh.x, 0.0} * (1.0 / std::sqrt(lensq)) : Vec3{1.0, 0.0, 0.0};
  Vec3 t2 = cross(vh, t1);
  double r = std::sqrt(xi.u);
  double phi = 2.0 * kPi * xi.v;
  double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  Vec3 h{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)};
  double len = length(h);
  // Only reachable at α = 0 with a point on the disk's rim: the mirror normal is the limit.
  return len > 0.0 ? h * (1.0 / len) : Vec3{0.0, 0.0, 1.0};
}

TangentFrame::TangentFrame(Vec3 normal) : n(normal) {
  double sign = std::copysign(1.0, n.z);
  double a = -1.0 / (sign + n.z);
  double b2 = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * b2, -sign * n.x};
  b = {b2, sign + n.y * n.y * a, -n.y};
}

}  // namespace facet::ibl
