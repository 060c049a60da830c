#include "facet/eval/grid_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "facet/ir/check.h"

namespace facet::eval {
namespace {

// The parameter that feeds a surface output directly, if it has one of the given types.
std::string feedingParam(const ir::Material& m, const char* output, std::initializer_list<ir::Type> types) {
  auto it = m.surface.outputs.find(output);
  if (it == m.surface.outputs.end()) return "";
  const ir::Value& v = m.surface.value(it->second);
  if (v.op != ir::Op::Param) return "";
  for (const ir::Param& p : m.params)
    if (p.name == v.name && std::find(types.begin(), types.end(), p.type) != types.end()) return p.name;
  return "";
}

const ir::Param* findParam(const ir::Material& m, const std::string& name) {
  for (const ir::Param& p : m.params)
    if (p.name == name) return &p;
  return nullptr;
}

double clampToRange(const ir::Param& p, double v) {
  if (p.rangeMin) v = std::max(v, *p.rangeMin);
  if (p.rangeMax) v = std::min(v, *p.rangeMax);
  return v;
}

// Whether the material is a metal where the grid does not sweep metallic: a constant metallic
// output of at least 0.5 (brushed_gold's `metallic = 1.0`).
bool constantMetal(const ir::Material& m) {
  auto it = m.surface.outputs.find("metallic");
  if (it == m.surface.outputs.end()) return false;
  const ir::Value& v = m.surface.value(it->second);
  return v.op == ir::Op::Constant && v.constant[0] >= 0.5;
}

// Base colours, sRGB-encoded as a colour picker shows them: a near-white dielectric, gold for
// metals (its measured f0, linear (1.00, 0.78, 0.34)), and a near-black for both.
constexpr double kBrightDielectric[3] = {0.90, 0.90, 0.90};
constexpr double kBrightMetal[3] = {1.00, 0.90, 0.62};
constexpr double kDark[3] = {0.05, 0.05, 0.05};

std::string formatList(const std::vector<double>& values) {
  std::string s;
  char buf[32];
  for (size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%g", i ? ", " : "", values[i]);
    s += buf;
  }
  return s;
}

}  // namespace

GridSweep gridSweep(const ir::Material& m) {
  GridSweep s;
  s.roughness = feedingParam(m, "roughness", {ir::Type::Float});
  s.metallic = feedingParam(m, "metallic", {ir::Type::Float});
  s.baseColor = feedingParam(m, "baseColor", {ir::Type::Vec3});
  return s;
}

std::vector<GridView> evaluationGrid(const ir::Material& m, const GridOptions& options) {
  const GridSweep sweep = gridSweep(m);
  std::vector<double> roughness =
      sweep.roughness.empty() || options.roughness.empty() ? std::vector<double>{0} : options.roughness;
  std::vector<double> metallic = sweep.metallic.empty() ? std::vector<double>{0} : std::vector<double>{0, 1};
  const int colours = sweep.baseColor.empty() ? 1 : 2;
  const int cols = int(roughness.size());
  const int rows = int(metallic.size()) * colours;

  runtime::Scene base;
  const uint32_t pps = std::max<uint32_t>(options.pixelsPerSphere, 8);
  base.width = uint32_t(cols) * pps;
  base.height = uint32_t(rows) * pps;
  base.tier = "reference";
  // A narrow field of view keeps the spheres round; the distance frames the grid's height (and
  // so its width: the image has the grid's aspect ratio), spheres 1 apart with radius 0.4.
  const double fovY = 20;
  base.camera.fovYDegrees = fovY;
  base.camera.position = {0, 0, 0.52 * rows / std::tan(fovY * 0.5 * 3.14159265358979 / 180.0) + 0.4};
  base.camera.target = {0, 0, 0};
  base.camera.farPlane = 1000;
  // f/16, 1/125 s, ISO 100 (the camera defaults): the sunny-16 exposure.
  runtime::Environment sky;  // the analytic sky, as examples/scenes/outdoor.json
  sky.luminance = 8000;
  base.environment = sky;
  runtime::PunctualLight lamp;
  lamp.position = {-0.5 * cols + 0.5, 0.5 * rows + 0.3, 1.5};
  lamp.intensity = 60000;  // candela: ~15 000 lux at 2 m, an eighth of the sun
  lamp.color = {1.0, 0.85, 0.65};
  lamp.range = 20;
  base.lights.push_back(lamp);

  int row = 0;
  for (double metal : metallic) {
    for (int c = 0; c < colours; ++c, ++row) {
      for (int col = 0; col < cols; ++col) {
        runtime::SceneObject o;
        o.material = m.name;
        o.radius = 0.4;
        o.position = {col - 0.5 * (cols - 1), 0.5 * (rows - 1) - row, 0};
        if (!sweep.roughness.empty())
          o.params[sweep.roughness] = {clampToRange(*findParam(m, sweep.roughness), roughness[size_t(col)])};
        if (!sweep.metallic.empty()) o.params[sweep.metallic] = {clampToRange(*findParam(m, sweep.metallic), metal)};
        if (!sweep.baseColor.empty()) {
          const ir::Param& p = *findParam(m, sweep.baseColor);
          const bool metalRow = sweep.metallic.empty() ? constantMetal(m) : metal >= 0.5;
          const double* srgb = c == 1 ? kDark : metalRow ? kBrightMetal : kBrightDielectric;
          std::vector<double> value;
          // colour parameters are given sRGB-encoded (scene format); plain vec3s are used as is.
          for (int k = 0; k < 3; ++k) value.push_back(clampToRange(p, p.isColor ? srgb[k] : ir::srgbToLinear(srgb[k])));
          o.params[sweep.baseColor] = value;
        }
        base.objects.push_back(o);
      }
    }
  }

  std::vector<GridView> views(2, {"", base});
  views[0].name = "frontal";  // the sun behind the camera, a little above and to the left
  views[0].scene.sun = runtime::Sun{-glm::normalize(glm::dvec3(0.35, 0.45, 1.0)), 110000, {1.0, 0.96, 0.9}};
  views[1].name = "grazing";  // the sun from the right, slightly above and behind the spheres
  views[1].scene.sun = runtime::Sun{-glm::normalize(glm::dvec3(1.0, 0.25, -0.25)), 110000, {1.0, 0.96, 0.9}};
  return views;
}

GridView shadowedGridView(const ir::Material& m, const GridOptions& options) {
  GridView view = evaluationGrid(m, options)[0];
  view.name = "shadowed";
  view.scene.sun->castShadows = true;
  // Every sphere's shadow, 0.57 m from its centre on the wall, and the wall's rim lie in the
  // image: the wall is the grid's size and a sphere's spacing more each way.
  const uint32_t pps = std::max<uint32_t>(options.pixelsPerSphere, 8);
  const double cols = double(view.scene.width / pps), rows = double(view.scene.height / pps);
  runtime::SceneObject wall;
  wall.mesh = "plane";
  wall.material = m.name;
  wall.position = {0, 0, kShadowWallZ};
  wall.rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(1, 0, 0));  // the plane's +y normal to +z
  wall.scale = {cols + 2, 1, rows + 2};
  view.scene.objects.push_back(wall);
  return view;
}

std::vector<std::string> describeSweep(const ir::Material& m, const GridOptions& options) {
  const GridSweep sweep = gridSweep(m);
  std::vector<std::string> lines;
  lines.push_back(sweep.roughness.empty()
                      ? "roughness: not swept (the `roughness` output is not a float parameter); one column"
                      : "roughness: params." + sweep.roughness + " over " + formatList(options.roughness) +
                            " (clamped to its declared range), one column each");
  lines.push_back(sweep.metallic.empty() ? "metallic: not swept (the `metallic` output is not a float parameter)"
                                         : "metallic: params." + sweep.metallic + " = 0 and 1, rows");
  lines.push_back(sweep.baseColor.empty()
                      ? "base colour: not swept (the `baseColor` output is not a color/vec3 parameter)"
                      : "base colour: params." + sweep.baseColor +
                            " bright (sRGB 0.90 grey; gold 1.00, 0.90, 0.62 on metals) and dark (sRGB 0.05), rows");
  return lines;
}

}  // namespace facet::eval
