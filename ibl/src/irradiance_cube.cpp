#include "facet/ibl/irradiance_cube.h"

#include "facet/ibl/spherical_harmonics.h"

namespace facet::ibl {

CubeImage tabulateIrradiance(const std::vector<Vec3>& coefficients, int size) {
  CubeImage cube(size);
  for (int face = 0; face < kCubeFaces; ++face)
    for (int row = 0; row < size; ++row)
      for (int column = 0; column < size; ++column)
        cube.setTexel(face, column, row,
                      evaluateShaderIrradiance(coefficients, cubeTexelDirection(size, face, column, row)));
  return cube;
}

}  // namespace facet::ibl
