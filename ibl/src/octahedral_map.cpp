#include "facet/ibl/octahedral_map.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {
namespace {

double signNotZero(double x) { return x >= 0.0 ? 1.0 : -1.0; }

// Texel coordinate of index i on one axis: its centre, pushed onto the edge for the outer ring.
double snappedCentre(int i, int size) {
  if (i == 0) return 0.0;
  if (i == size - 1) return 1.0;
  return (i + 0.5) / size;
}

}  // namespace

Vec3 OctahedralImage::texel(int column, int row) const {
  const float* p = &rgb[(size_t(row) * size_t(size) + size_t(column)) * 3];
  return {p[0], p[1], p[2]};
}

void OctahedralImage::setTexel(int column, int row, Vec3 value) {
  float* p = &rgb[(size_t(row) * size_t(size) + size_t(column)) * 3];
  p[0] = static_cast<float>(value.x);
  p[1] = static_cast<float>(value.y);
  p[2] = static_cast<float>(value.z);
}

void octahedralCoordinates(Vec3 d, double* u, double* v) {
  double l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  double px = d.x / l1, py = d.z / l1;
  if (d.y < 0.0) {
    double fx = (1.0 - std::abs(py)) * signNotZero(px);
    double fy = (1.0 - std::abs(px)) * signNotZero(py);
    px = fx;
    py = fy;
  }
  *u = 0.5 * px + 0.5;
  *v = 0.5 * py + 0.5;
}

Vec3 octahedralDirection(double u, double v) {
  double px = 2.0 * u - 1.0, py = 2.0 * v - 1.0;
  double y = 1.0 - std::abs(px) - std::abs(py);
  if (y < 0.0) {
    double fx = (1.0 - std::abs(py)) * signNotZero(px);
    double fy = (1.0 - std::abs(px)) * signNotZero(py);
    px = fx;
    py = fy;
  }
  return normalize(Vec3{px, y, py});
}

Vec3 octahedralTexelDirection(int size, int column, int row) {
  return octahedralDirection(snappedCentre(column, size), snappedCentre(row, size));
}

Vec3 sampleBilinear(const OctahedralImage& image, double u, double v) {
  double x = u * image.size - 0.5, y = v * image.size - 0.5;
  double x0 = std::floor(x), y0 = std::floor(y);
  double fx = x - x0, fy = y - y0;
  auto at = [&](double cx, double cy) {
    int c = std::clamp(int(cx), 0, image.size - 1), r = std::clamp(int(cy), 0, image.size - 1);
    return image.texel(c, r);
  };
  Vec3 top = at(x0, y0) * (1.0 - fx) + at(x0 + 1, y0) * fx;
  Vec3 bottom = at(x0, y0 + 1) * (1.0 - fx) + at(x0 + 1, y0 + 1) * fx;
  return top * (1.0 - fy) + bottom * fy;
}

}  // namespace facet::ibl
