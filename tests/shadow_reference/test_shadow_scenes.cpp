// The shadow flags as read from scene files, and the hard-case scenes of tests/data/scenes/shadows
// (docs/shadows.md): their reference visibility, counted, and what each case is about checked.
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/shadow_reference/camera_rays.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"
#include "test_support.h"

namespace facet::shadow_reference {
namespace {

const std::string kScene = R"({
  "sun": {"direction": [0, -1, 0], "castShadows": true},
  "shadows": {"cascades": 2},
  "objects": [
    {"mesh": "plane", "material": "red_plastic", "receiveShadows": false},
    {"material": "red_plastic", "castShadows": false},
    {"material": "red_plastic"}
  ]
})";

// One flag of every object, in scene order.
std::vector<bool> objectFlags(const facet::runtime::Scene& scene, bool facet::runtime::SceneObject::*flag) {
  std::vector<bool> out;
  for (const facet::runtime::SceneObject& o : scene.objects) out.push_back(o.*flag);
  return out;
}

TEST(ShadowScene, ReadsTheFlagsWithTheirDefaults) {
  std::string error;
  std::optional<ShadowScene> s = parseShadowScene("s.json", kScene, &error);
  ASSERT_TRUE(s) << error;
  EXPECT_TRUE(s->scene.sun->castShadows);
  EXPECT_EQ(objectFlags(s->scene, &facet::runtime::SceneObject::castShadows), (std::vector<bool>{true, false, true}));
  EXPECT_EQ(objectFlags(s->scene, &facet::runtime::SceneObject::receiveShadows),
            (std::vector<bool>{false, true, true}));
  ASSERT_EQ(s->scene.objects.size(), 3u);
  EXPECT_EQ(s->scene.objects[0].mesh, "plane");
  s = parseShadowScene("s.json", R"({"sun": {"direction": [0, -1, 0]}, "objects": [{"material": "m"}]})", &error);
  ASSERT_TRUE(s) << error;
  EXPECT_FALSE(s->scene.sun->castShadows);
  EXPECT_EQ(objectFlags(s->scene, &facet::runtime::SceneObject::castShadows), std::vector<bool>{true});
  EXPECT_EQ(objectFlags(s->scene, &facet::runtime::SceneObject::receiveShadows), std::vector<bool>{true});
}

TEST(ShadowScene, WrongValuesNameTheirPointer) {
  struct Case {
    std::string text, error;
  };
  const Case cases[] = {
      {R"({"objects": [{"material": "m"}, {"material": "m", "castShadows": 1}]})",
       "s.json: error: /objects/1/castShadows: expected true or false"},
      {R"({"objects": [{"material": "m", "receiveShadows": "yes"}]})",
       "s.json: error: /objects/0/receiveShadows: expected true or false"},
      {R"({"sun": {"castShadows": null}, "objects": []})", "s.json: error: /sun/castShadows: expected true or false"},
      {R"({"shadows": 4})", "s.json: error: /shadows: expected an object"},
      // Everything else is the scene reader's, at the same pointer as in the file.
      {R"({"objects": [{"material": "m", "castShadow": true}]})",
       "s.json: error: /objects/0/castShadow: unknown key 'castShadow'"},
      {"{\n  \"objects\": [,]\n}", "s.json:2:15: error: invalid JSON: "},
  };
  for (const Case& c : cases) {
    std::string error;
    EXPECT_FALSE(parseShadowScene("s.json", c.text, &error)) << c.text;
    EXPECT_EQ(error.substr(0, c.error.size()), c.error) << c.text;
  }
}

struct HardCase {
  const char* name;
  ReferenceCounts counts;  // at the scene's size, footprint 0
};

// Counted by facet-measure-shadows (docs/shadows.md has the command); the reference is
// deterministic, so any change here is a change of the reference or of the scene.
const HardCase kHardCases[] = {
    {"behind_camera", {.sky = 18176, .facesAway = 0, .lit = 33458, .occluded = 13902, .partial = 0}},
    {"cascade_boundary", {.sky = 25080, .facesAway = 0, .lit = 39484, .occluded = 972, .partial = 0}},
    {"contact", {.sky = 6773, .facesAway = 1055, .lit = 54512, .occluded = 3196, .partial = 0}},
    {"grazing_sun", {.sky = 23296, .facesAway = 0, .lit = 38823, .occluded = 3417, .partial = 0}},
    {"thin_pole", {.sky = 16409, .facesAway = 173, .lit = 48742, .occluded = 212, .partial = 0}},
};

struct Loaded {
  ShadowScene scene;
  ReferenceImage image;
};

Loaded load(const std::string& name, bool secondObjectCasts = true) {
  std::string error;
  const std::string path = test::sourceDir() + "/tests/data/scenes/shadows/" + name + ".json";
  std::optional<ShadowScene> s = loadShadowScene(path, &error);
  EXPECT_TRUE(s) << error;
  EXPECT_TRUE(s->scene.sun->castShadows) << name;
  if (!secondObjectCasts) s->scene.objects.at(1).castShadows = false;
  std::optional<SunVisibility> sun = SunVisibility::build(*s, &error);
  EXPECT_TRUE(sun) << error;
  ReferenceImage image = renderReference(*s, *sun, {});
  return {std::move(*s), std::move(image)};
}

bool groundShadow(const ReferenceImage& image, int x, int y) {
  if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) return false;
  const ReferencePixel& p = image.pixels[size_t(y) * image.width + size_t(x)];
  return p.kind == PixelKind::Surface && p.object == 0 && p.visibility == 0;
}

bool seesObject(const ReferenceImage& image, int x, int y, uint32_t object) {
  if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) return false;
  const ReferencePixel& p = image.pixels[size_t(y) * image.width + size_t(x)];
  return p.kind != PixelKind::Sky && p.object == object;
}

// The 8-connected groups of shadowed ground pixels.
int shadowComponents(const ReferenceImage& image) {
  std::vector<bool> seen(image.pixels.size());
  int components = 0;
  for (int y = 0; y < int(image.height); ++y)
    for (int x = 0; x < int(image.width); ++x) {
      if (!groundShadow(image, x, y) || seen[size_t(y) * image.width + size_t(x)]) continue;
      ++components;
      std::vector<std::pair<int, int>> stack{{x, y}};
      seen[size_t(y) * image.width + size_t(x)] = true;
      while (!stack.empty()) {
        auto [px, py] = stack.back();
        stack.pop_back();
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = px + dx, ny = py + dy;
            if (!groundShadow(image, nx, ny) || seen[size_t(ny) * image.width + size_t(nx)]) continue;
            seen[size_t(ny) * image.width + size_t(nx)] = true;
            stack.push_back({nx, ny});
          }
      }
    }
  return components;
}

// Shadowed ground pixels next to a pixel of the caster (object 1): where the shadow meets it.
int shadowTouchingCaster(const ReferenceImage& image) {
  int touching = 0;
  for (int y = 0; y < int(image.height); ++y)
    for (int x = 0; x < int(image.width); ++x) {
      if (!groundShadow(image, x, y)) continue;
      bool next = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) next = next || seesObject(image, x + dx, y + dy, 1);
      touching += next;
    }
  return touching;
}

TEST(ShadowHardCases, ReferenceCounts) {
  for (const HardCase& c : kHardCases) {
    const ReferenceCounts counts = countReference(load(c.name).image);
    EXPECT_EQ(counts.sky, c.counts.sky) << c.name;
    EXPECT_EQ(counts.facesAway, c.counts.facesAway) << c.name;
    EXPECT_EQ(counts.lit, c.counts.lit) << c.name;
    EXPECT_EQ(counts.occluded, c.counts.occluded) << c.name;
    EXPECT_EQ(counts.partial, c.counts.partial) << c.name;
  }
}

// The ground under a 3-degree sun: with the box not casting, no ground pixel is shadowed (the
// reference itself has no acne: the ray epsilon and the skipped receiving triangle), and the box's
// long shadow is one piece.
TEST(ShadowHardCases, GrazingSunGroundIsLitWithoutTheCaster) {
  EXPECT_EQ(countReference(load("grazing_sun", false).image).occluded, 0u);
  EXPECT_EQ(shadowComponents(load("grazing_sun").image), 1);
}

// The box standing on the ground: its shadow starts at its foot.
TEST(ShadowHardCases, ContactShadowMeetsTheBox) {
  const Loaded c = load("contact");
  EXPECT_EQ(shadowComponents(c.image), 1);
  EXPECT_GT(shadowTouchingCaster(c.image), 20);
}

// The 5 cm pole: its shadow is one connected piece, from the pole's foot.
TEST(ShadowHardCases, ThinPoleShadowIsConnected) {
  const Loaded c = load("thin_pole");
  EXPECT_EQ(shadowComponents(c.image), 1);
  EXPECT_GT(shadowTouchingCaster(c.image), 0);
}

// The caster is behind the camera: no pixel sees it, its shadow fills part of the view.
TEST(ShadowHardCases, CasterBehindTheCameraCasts) {
  const Loaded c = load("behind_camera");
  for (const ReferencePixel& p : c.image.pixels) ASSERT_FALSE(p.kind != PixelKind::Sky && p.object == 1);
  EXPECT_GT(countReference(c.image).occluded, 10000u);
  EXPECT_EQ(shadowComponents(c.image), 1);
}

// The wall's shadow along the view: one unbroken strip from the bottom of the image to beyond
// 60 m, where any cascade split scheme has changed cascade at least once.
TEST(ShadowHardCases, CascadeBoundaryStripIsUnbroken) {
  const Loaded c = load("cascade_boundary");
  EXPECT_EQ(shadowComponents(c.image), 1);
  const CameraRays camera(c.scene.scene);
  int top = int(c.image.height), bottom = -1;
  double farthest = 0;
  for (int y = 0; y < int(c.image.height); ++y)
    for (int x = 0; x < int(c.image.width); ++x)
      if (groundShadow(c.image, x, y)) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
        const Ray ray = camera.ray(uint32_t(x), uint32_t(y));
        farthest = std::max(farthest, -ray.origin.y / ray.direction.y);
      }
  EXPECT_EQ(bottom, int(c.image.height) - 1);
  EXPECT_GT(farthest, 60);
  for (int y = top; y <= bottom; ++y) {
    bool any = false;
    for (int x = 0; x < int(c.image.width); ++x) any = any || groundShadow(c.image, x, y);
    EXPECT_TRUE(any) << "row " << y;
  }
}

}  // namespace
}  // namespace facet::shadow_reference
