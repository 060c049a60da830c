// The built-in evaluation scene of `matc eval` (docs/eval.md, "The evaluation grid"): spheres of
// the material across roughness × metallic × dark/bright base colour, seen twice — lit by a frontal
// sun and by a grazing one — each time with a point light and an analytic sky. Built in code from
// the material's parameters; `--scene` replaces it with a scene file.
#pragma once

#include <string>
#include <vector>

#include "facet/ir/module.h"
#include "facet/scene/scene.h"

namespace facet::eval {

struct GridOptions {
  std::vector<double> roughness = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0};  // one column each
  uint32_t pixelsPerSphere = 64;                                   // image size: columns × rows of these
};

// Which of the material's parameters the grid sweeps: the one that feeds the surface output
// directly (`roughness = params.r` sweeps `r`), of a type the sweep can set; "" when the output is
// computed or constant, and then the grid has one column (roughness) or row (the others) for it.
struct GridSweep {
  std::string roughness;  // float parameter feeding `roughness`
  std::string metallic;   // float parameter feeding `metallic`
  std::string baseColor;  // color or vec3 parameter feeding `baseColor`
};
GridSweep gridSweep(const ir::Material& material);

struct GridView {
  std::string name;      // "frontal" | "grazing"
  runtime::Scene scene;  // tier "reference"; the caller sets the tier it renders
};

// The views of the grid for the material (which must be lit or unlit; an unlit material gets the
// same spheres, its lights simply unused). Rows top to bottom: for each metallic value (0 then 1,
// when swept), bright then dark base colour (when swept).
std::vector<GridView> evaluationGrid(const ir::Material& material, const GridOptions& options = {});

// The "shadowed" view (`matc eval --shadows`, docs/eval.md): the frontal view's spheres before a
// wall of the material, the sun casting (the default `shadows` block: a 2048² atlas, 4 cascades),
// each sphere's shadow on the wall beside it, down and to the left. Its receivers are the
// `<tier>.dir1.pt1.sh4` variants.
GridView shadowedGridView(const ir::Material& material, const GridOptions& options = {});

// The wall of the shadowed view: a plane facing the camera at z = kShadowWallZ, the spheres' centres
// at z = 0 (radius 0.4), so a sphere's shadow centre lies kShadowWallZ × (the sun's x, y ÷ its z)
// from its centre.
inline constexpr double kShadowWallZ = -1.0;

// One line per swept axis, for reports: "roughness: params.roughness over 0, 0.2, ..., 1", or why
// it is not swept.
std::vector<std::string> describeSweep(const ir::Material& material, const GridOptions& options = {});

}  // namespace facet::eval
