#include "facet/ibl/cube_map.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {

Vec3 CubeImage::texel(int face, int column, int row) const {
  size_t i = ((size_t(face) * size_t(size) + size_t(row)) * size_t(size) + size_t(column)) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void CubeImage::setTexel(int face, int column, int row, Vec3 value) {
  size_t i = ((size_t(face) * size_t(size) + size_t(row)) * size_t(size) + size_t(column)) * 3;
  rgb[i] = float(value.x);
  rgb[i + 1] = float(value.y);
  rgb[i + 2] = float(value.z);
}

void cubeCoordinates(Vec3 d, int* face, double* s, double* t) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  double sc, tc, m;
  if (ax >= ay && ax >= az) {
    m = ax;
    *face = d.x >= 0 ? 0 : 1;
    sc = d.x >= 0 ? -d.z : d.z;
    tc = -d.y;
  } else if (ay >= az) {
    m = ay;
    *face = d.y >= 0 ? 2 : 3;
    sc = d.x;
    tc = d.y >= 0 ? d.z : -d.z;
  } else {
    m = az;
    *face = d.z >= 0 ? 4 : 5;
    sc = d.z >= 0 ? d.x : -d.x;
    tc = -d.y;
  }
  *s = 0.5 * (sc / m + 1.0);
  *t = 0.5 * (tc / m + 1.0);
}

Vec3 cubeDirection(int face, double s, double t) {
  const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
  switch (face) {
    case 0: return normalize({1.0, -tc, -sc});
    case 1: return normalize({-1.0, -tc, sc});
    case 2: return normalize({sc, 1.0, tc});
    case 3: return normalize({sc, -1.0, -tc});
    case 4: return normalize({sc, -tc, 1.0});
    default: return normalize({-sc, -tc, -1.0});
  }
}

Vec3 cubeTexelDirection(int size, int face, int column, int row) {
  return cubeDirection(face, (column + 0.5) / size, (row + 0.5) / size);
}

namespace {

// Texel (column, row) of `face`, where one of the two may lie one texel outside the face: that
// texel is the neighbouring face's, found by the direction through its would-be centre (on the
// face's plane, extended). Outside in both: the corner, where three faces meet, is the mean of
// the three texels around it, as Vulkan specifies for cube map corners.
Vec3 seamlessTexel(const CubeImage& image, int face, int column, int row) {
  const int n = image.size;
  const bool columnOut = column < 0 || column >= n, rowOut = row < 0 || row >= n;
  if (!columnOut && !rowOut) return image.texel(face, column, row);
  const int c = std::clamp(column, 0, n - 1), r = std::clamp(row, 0, n - 1);
  if (columnOut && rowOut)
    return (seamlessTexel(image, face, column, r) + seamlessTexel(image, face, c, row) + image.texel(face, c, r)) *
           (1.0 / 3.0);
  // cubeDirection extends linearly beyond [0, 1]: the point half a texel past the edge.
  const Vec3 d = cubeDirection(face, (column + 0.5) / n, (row + 0.5) / n);
  int other = 0;
  double s = 0, t = 0;
  cubeCoordinates(d, &other, &s, &t);
  return image.texel(other, std::clamp(int(s * n), 0, n - 1), std::clamp(int(t * n), 0, n - 1));
}

}  // namespace

Vec3 sampleBilinear(const CubeImage& image, Vec3 direction) {
  int face = 0;
  double s = 0, t = 0;
  cubeCoordinates(direction, &face, &s, &t);
  double x = s * image.size - 0.5, y = t * image.size - 0.5;
  double x0 = std::floor(x), y0 = std::floor(y);
  double fx = x - x0, fy = y - y0;
  auto at = [&](double cx, double cy) { return seamlessTexel(image, face, int(cx), int(cy)); };
  Vec3 top = at(x0, y0) * (1.0 - fx) + at(x0 + 1, y0) * fx;
  Vec3 bottom = at(x0, y0 + 1) * (1.0 - fx) + at(x0 + 1, y0 + 1) * fx;
  return top * (1.0 - fy) + bottom * fy;
}

}  // namespace facet::ibl
