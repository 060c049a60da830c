// ibl/irradiance_cube.h
// SH irradiance tabulated in a cube map: what the `cube` diffuse reads (chunks/ambient_irradiance_cube.glsl)
// in place of evaluating the SH sum per pixel. Each texel holds the shader's sum at its centre
// direction, so the bilinear read differs from the per-pixel sum only by interpolating a smooth
// function (a quadratic polynomial in the direction, clamped at 0) between texel centres.
#pragma once

#include <vector>

#include "facet/ibl/cube_map.h"
#include "facet/ibl/vec3.h"

namespace facet::ibl {

/// A size² cube (the API face order, cube_map.h) of evaluateShaderIrradiance(coefficients, d) at
/// every texel's centre direction d: irradiance / π in the coefficients' units.
CubeImage tabulateIrradiance(const std::vector<Vec3>& coefficients, int size);

}  // namespace facet::ibl
