#include "facet/ibl/equirect_image.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {

Vec3 EquirectImage::texel(int column, int row) const {
  const float* p = &rgb[(size_t(row) * size_t(width) + size_t(column)) * 3];
  return {p[0], p[1], p[2]};
}

void EquirectImage::setTexel(int column, int row, Vec3 value) {
  float* p = &rgb[(size_t(row) * size_t(width) + size_t(column)) * 3];
  p[0] = static_cast<float>(value.x);
  p[1] = static_cast<float>(value.y);
  p[2] = static_cast<float>(value.z);
}

Vec3 equirectDirection(const EquirectImage& image, int column, int row) {
  double theta = kPi * (row + 0.5) / image.height;
  double phi = 2.0 * kPi * (column + 0.5) / image.width;
  double sinTheta = std::sin(theta);
  return {sinTheta * std::cos(phi), std::cos(theta), sinTheta * std::sin(phi)};
}

void equirectCoordinates(Vec3 direction, double* s, double* t) {
  double phi = std::atan2(direction.z, direction.x);  // (−π, π]
  double u = phi / (2.0 * kPi);
  *s = u < 0.0 ? u + 1.0 : u;
  *t = std::acos(std::clamp(direction.y, -1.0, 1.0)) / kPi;
}

double equirectTexelSolidAngle(const EquirectImage& image, int row) {
  double theta0 = kPi * row / image.height;
  double theta1 = kPi * (row + 1) / image.height;
  return (2.0 * kPi / image.width) * (std::cos(theta0) - std::cos(theta1));
}

Vec3 sampleBilinear(const EquirectImage& image, double s, double t) {
  double x = s * image.width - 0.5;
  double y = std::clamp(t * image.height - 0.5, 0.0, double(image.height - 1));
  double x0 = std::floor(x);
  double y0 = std::floor(y);
  double fx = x - x0;
  double fy = y - y0;
  auto wrap = [&](double c) {
    int i = static_cast<int>(c) % image.width;
    return i < 0 ? i + image.width : i;
  };
  int c0 = wrap(x0);
  int c1 = wrap(x0 + 1.0);
  int r0 = static_cast<int>(y0);
  int r1 = std::min(r0 + 1, image.height - 1);
  Vec3 top = image.texel(c0, r0) * (1.0 - fx) + image.texel(c1, r0) * fx;
  Vec3 bottom = image.texel(c0, r1) * (1.0 - fx) + image.texel(c1, r1) * fx;
  return top * (1.0 - fy) + bottom * fy;
}

EquirectImage downsampleEquirect(const EquirectImage& image) {
  EquirectImage half(image.width / 2, image.height / 2);
  for (int row = 0; row < half.height; ++row) {
    // Both children in a column share the width, so their solid angles weigh by rows only.
    double w0 = equirectTexelSolidAngle(image, 2 * row);
    double w1 = equirectTexelSolidAngle(image, 2 * row + 1);
    double norm = 1.0 / (2.0 * (w0 + w1));
    for (int column = 0; column < half.width; ++column) {
      Vec3 top = image.texel(2 * column, 2 * row) + image.texel(2 * column + 1, 2 * row);
      Vec3 bottom = image.texel(2 * column, 2 * row + 1) + image.texel(2 * column + 1, 2 * row + 1);
      half.setTexel(column, row, (top * w0 + bottom * w1) * norm);
    }
  }
  return half;
}

Vec3 meanRadiance(const EquirectImage& image) {
  Vec3 sum;
  double area = 0;
  for (int row = 0; row < image.height; ++row) {
    double w = equirectTexelSolidAngle(image, row);
    for (int column = 0; column < image.width; ++column) sum += image.texel(column, row) * w;
    area += w * image.width;
  }
  return sum * (1.0 / area);
}

}  // namespace facet::ibl
