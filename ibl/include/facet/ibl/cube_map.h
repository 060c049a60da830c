// ibl/cube_map.h
// A float RGB environment as the six faces of a cube map, the layout the shaders sample with
// samplerCube: the hardware picks the face and its texel from the direction as it is, so the
// lookup costs the shader no arithmetic (an octahedral map's fold costs 0.11 Mali-G57 cycles per
// lookup, an equirect atan + acos 0.34: docs/platform-facts.md).
//
// Faces in the API order +X, −X, +Y, −Y, +Z, −Z (layer i of a Vulkan cube image,
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), each size × size texels, row 0 at t = 0. Face selection
// and (s, t) follow the Vulkan specification's cube map table ("Cube Map Face Selection", the
// same as OpenGL ES 3.0 §3.8.10): with m the major axis's magnitude,
//   +X: (sc, tc) = (−z, −y)   −X: (z, −y)   +Y: (x, z)   −Y: (x, −z)   +Z: (x, −y)   −Z: (−x, −y)
//   s = (sc / m + 1) / 2,  t = (tc / m + 1) / 2
// Seams: the GPU filters across faces (Vulkan and GLES 3.0 always; desktop GL once
// GL_TEXTURE_CUBE_MAP_SEAMLESS is enabled, which the GL backend does), so unlike the octahedral
// map the faces need no shared border.
#pragma once

#include <vector>

#include "facet/ibl/vec3.h"

namespace facet::ibl {

inline constexpr int kCubeFaces = 6;

struct CubeImage {
  int size = 0;            // each face size × size texels
  std::vector<float> rgb;  // 6 × size × size × 3: face-major, then row-major, row 0 at t = 0

  CubeImage() = default;
  explicit CubeImage(int n) : size(n), rgb(size_t(kCubeFaces) * size_t(n) * size_t(n) * 3, 0.0f) {}

  Vec3 texel(int face, int column, int row) const;
  void setTexel(int face, int column, int row, Vec3 value);
};

/// The face (0 … 5, the API order) and face coordinates (s, t) ∈ [0, 1]² of a direction (need not
/// be unit length, must not be 0). Ties between axes go to x, then y, as the table is read.
void cubeCoordinates(Vec3 direction, int* face, double* s, double* t);

/// The unit direction at coordinates (s, t) of `face`.
Vec3 cubeDirection(int face, double s, double t);

/// The unit direction through a texel's centre.
Vec3 cubeTexelDirection(int size, int face, int column, int row);

/// Bilinear sample as the GPU's seamless cube filter does it: within half a texel of an edge the
/// neighbouring face's edge texels take the place of the missing ones, and at a corner the mean of
/// the three texels that meet there (the Vulkan specification's cube map edge handling).
Vec3 sampleBilinear(const CubeImage& image, Vec3 direction);

}  // namespace facet::ibl
