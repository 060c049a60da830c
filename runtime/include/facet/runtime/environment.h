// Image-based lighting of a scene, computed on the CPU with facet_ibl (docs/ibl.md) and turned into
// what the shaders read: SH irradiance coefficients for the frame block, the prefiltered
// environment (RGBA16F, explicit mips) and the split-sum DFG table (RG16F).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "facet/ibl/dfg_lut.h"
#include "facet/runtime/render_backend.h"
#include "facet/scene/scene.h"

namespace facet::runtime {

// The equirect size an environment image or the analytic sky is brought to before SH projection
// and prefiltering: small on purpose (docs/ibl.md) — the rough levels hold little detail and the
// mirror level is only as sharp as 128 texels around the horizon.
inline constexpr int kEnvironmentWidth = 128;
inline constexpr int kEnvironmentHeight = 64;
// Level-0 face size of the prefiltered environment the shaders sample, a cube map
// (facet/ibl/cube_map.h): at 64² 256 texels run around the horizon (the equirect source has 128)
// and the last (r = 1) of the 5 levels keeps 4² per face.
inline constexpr int kEnvironmentMapSize = 64;

// Everything pre-exposed (× the camera exposure), like the lights (docs/lighting-units.md).
struct EnvironmentLighting {
  // shaderIrradianceCoefficients of the SH projection to band 4: irradiance / π = Σ sh[k] p_k(n),
  // SH3's nine then band 4's (abi::FrameUniforms::sh's order).
  std::array<std::array<float, 3>, abi::kShFrameCoefficients> sh{};
  std::array<float, 3> meanRadiance{};
  uint32_t width = 0;  // level 0's faces, square: level m's are width >> m × height >> m
  uint32_t height = 0;
  // RGB floats per level: six faces one after the other (+X, −X, +Y, −Y, +Z, −Z), each row 0 at
  // t = 0 (facet/ibl/cube_map.h).
  std::vector<std::vector<float>> levels;
};

// The scene's environment: its `environment` (image or analytic sky) or, without one, the
// constant sky of `sky.luminance` (exact: SH band 0 only, every level constant; 0 gives a black
// environment). Fails with a message on an unreadable or unsuitable image. An image or analytic
// sky is prefiltered on one thread per core, joined before it returns (0.16–0.20 s on two cores,
// docs/ibl.md; the levels are the same bits on any number of cores).
std::optional<EnvironmentLighting> buildEnvironmentLighting(const Scene& scene, double exposure, std::string* error);

// The prefiltered levels as the texture the shaders sample: an RGBA16F (alpha 1) cube map, linear
// filtering within and between levels and across faces (chunks/environment_cube.glsl).
Texture environmentTexture(const EnvironmentLighting& lighting);

// The split-sum DFG table: facet::ibl::generateDfgLut(64) (2048 samples per texel, ~1 s on one
// core), computed at build time and linked as data (facet::ibl::embeddedDfgLut), so loading it
// costs no integration. `texels` holds (B, A + B) per texel,
// column = n·v, row = roughness, both at (i + 0.5)/64.
using DfgTable = ibl::DfgLut;
const DfgTable& dfgTable();
// The table as RGBA16F (one level, bilinear, clamp to edge), made once per process: R and G the
// DFG terms, B and A the sheen's corrected albedo min(E, 1) and lobe scale 1/max(E, 1)
// (facet::ibl::embeddedSheenLut, sheen_lut.h), which cloth materials read (chunks/shading_cloth.glsl).
const Texture& dfgTexture();

// The irradiance cube the `cube` diffuse reads (chunks/ambient_irradiance_cube.glsl): SH3's
// irradiance / π from lighting.sh[0..8] (what the SH diffuse sums per pixel) at every texel's
// centre, an RGBA16F cube of one level, abi::kIrradianceMapSize² a face, bilinear across faces
// (facet::ibl::tabulateIrradiance; 0.50 ms of CPU, docs/ibl.md).
Texture irradianceTexture(const EnvironmentLighting& lighting);

// An app's frame lit by `lighting`: its SH coefficients into the frame block, its mean radiance
// as the clear colour (what a constant sky's background is), and `environment`
// (environmentTexture(lighting)), `irradiance` (irradianceTexture(lighting)), both kept alive by
// the caller while the frame is rendered, and the DFG table bound at their shader_abi.h slots.
// SceneFrame does the same for scenes.
void setEnvironment(FrameDesc& frame, const EnvironmentLighting& lighting, const Texture& environment,
                    const Texture& irradiance);

// IEEE binary16 bits of a float, rounded to nearest even; beyond the largest finite half
// (65504) it saturates there rather than becoming infinity, like the shaders' saturateMediump.
uint16_t floatToHalf(float value);

}  // namespace facet::runtime
