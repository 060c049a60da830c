// ibl/prefilter_environment.h
// The lighting half of the split sum (Karis 2013): the environment convolved with the GGX lobe
// for a range of roughness values, one mip level per roughness, for the shader to fetch at the
// reflected direction with textureLod(environment, uv(R), lod).
//
// Mapping: level m of `levels` holds the perceptual roughness r_m with r_m (2 − r_m) = m /
// (levels − 1), so the shader uses lod = (levels − 1) · r (2 − r) (Guy's Filament mobile talk,
// "Roughness mapping"): more levels for glossy surfaces, where the lobe changes fastest with r
// and a blend of two levels is furthest from the lobe between them (docs/eval.md, "The ground
// truth", has what it gained over the linear lod = (levels − 1) · r). Level m is the source's
// resolution halved m times (an equirect 2h × h stays 2h/2^m × h/2^m), level 0 is the source
// itself (r = 0 is a mirror).
//
// Per output texel with direction n the lobe assumes n = v = r (Karis 2013: the isotropic lobe
// loses its stretch at grazing angles, the price of a 2D table), importance-samples h ~ D n·h, and
// weights each reflected l by n·l. Each sample reads the source at the mip whose texel covers
// the sample's share of the lobe, lod = ½ log2(Ω_sample / Ω_texel) + lodBias with Ω_sample =
// 1 / (N pdf(l)) and pdf(l) = D / 4 (Křivánek & Colbert 2008, "Real-time Shading with Filtered
// Importance Sampling", and GPU Gems 3 ch. 20), so a few hundred samples suffice even with a
// small bright sun instead of producing fireflies (error measured in docs/ibl.md). Ω_texel is
// the solid angle of the source texel under the sample, so near the poles, where equirect texels
// are narrow, samples read blurrier mips. The coarsest source mip read has 8 rows (see
// prefilter_environment.cpp).
#pragma once

#include <vector>

#include "facet/ibl/cube_map.h"
#include "facet/ibl/equirect_image.h"

namespace facet::ibl {

struct PrefilterOptions {
  int levels = 5;  // Filament's talk: 256² down to 16², the last one doubling as diffuse
  // GGX samples per output texel (one at r = 0, where all coincide). 512: docs/ibl.md has the
  // error against the exact lobe integral for 256 and 512.
  int samples = 512;
  // Added to the source lod. Křivánek & Colbert add 1 (more blur, less noise); against the exact
  // lobe integral 0 gave about half the error on Facet's test skies (docs/ibl.md).
  double lodBias = 0.0;
  // Threads for prefilterEnvironmentCube (0: std::thread::hardware_concurrency()). The levels are
  // the same whatever the count; a scene load spends most of its CPU time here (docs/ibl.md).
  int threads = 0;
};

/// Perceptual roughness of `level`: 1 − √(1 − level / (levels − 1)), 0 when levels == 1.
double prefilterLevelRoughness(int level, int levels);

/// The mip chain, levels[0] at the source's resolution. The source must be 2h × h with h
/// divisible by 2^(levels − 1); throws std::invalid_argument otherwise.
std::vector<EquirectImage> prefilterEnvironment(const EquirectImage& source, const PrefilterOptions& options = {});

/// The same lobe averages, from the same equirect source, written as cube map levels (what the
/// runtime uploads; cube_map.h): level m has faces of (size >> m)², each texel the average around
/// cubeTexelDirection. size must be divisible by 2^(levels − 1), and the source as above; throws
/// std::invalid_argument otherwise.
std::vector<CubeImage> prefilterEnvironmentCube(const EquirectImage& source, int size,
                                                const PrefilterOptions& options = {});

}  // namespace facet::ibl
