// The shadow flags as read from scene files, and the hard-case scenes of tests/data/scenes/shadows
// (docs/shadows.md): their reference visibility, counted, and what each case is about checked.
#include <gtest/gtest.h>

#include <set>

#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"
#include "test_support.h"

namespace facet::shadow_reference {
namespace {

const std::string kScene = R"({
  "sun": {"direction": [0, -1, 0], "castShadows": true},
  "shadows": {"anything": "the renderer's"},
  "objects": [
    {"mesh": "plane", "material": "red_plastic", "receiveShadows": false},
    {"material": "red_plastic", "castShadows": false},
    {"material": "red_plastic"}
  ]
})";

TEST(ShadowScene, ReadsTheFlagsWithTheirDefaults) {
  std::string error;
  std::optional<ShadowScene> s = parseShadowScene("s.json", kScene, &error);
  ASSERT_TRUE(s) << error;
  EXPECT_TRUE(s->sunCastsShadows);
  EXPECT_EQ(s->casts, (std::vector<bool>{true, false, true}));
  EXPECT_EQ(s->receives, (std::vector<bool>{false, true, true}));
  ASSERT_EQ(s->scene.objects.size(), 3u);
  EXPECT_EQ(s->scene.objects[0].mesh, "plane");
  s = parseShadowScene("s.json", R"({"sun": {"direction": [0, -1, 0]}, "objects": [{"material": "m"}]})", &error);
  ASSERT_TRUE(s) << error;
  EXPECT_FALSE(s->sunCastsShadows);
  EXPECT_EQ(s->casts, std::vector<bool>{true});
  EXPECT_EQ(s->receives, std::vector<bool>{true});
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

ReferenceImage reference(const std::string& name, const ShadowScene** keep = nullptr) {
  static std::map<std::string, ShadowScene> scenes;
  std::string error;
  const std::string path = test::sourceDir() + "/tests/data/scenes/shadows/" + name + ".json";
  std::optional<ShadowScene> s = loadShadowScene(path, &error);
  EXPECT_TRUE(s) << error;
  EXPECT_TRUE(s->sunCastsShadows) << name;
  std::optional<SunVisibility> sun = SunVisibility::build(*s, &error);
  EXPECT_TRUE(sun) << error;
  ReferenceImage image = renderReference(*s, *sun, {});
  scenes[name] = std::move(*s);
  if (keep) *keep = &scenes[name];
  return image;
}

TEST(ShadowHardCases, ReferenceCounts) {
  for (const HardCase& c : kHardCases) {
    const ReferenceCounts counts = countReference(reference(c.name));
    EXPECT_EQ(counts.sky, c.counts.sky) << c.name;
    EXPECT_EQ(counts.facesAway, c.counts.facesAway) << c.name;
    EXPECT_EQ(counts.lit, c.counts.lit) << c.name;
    EXPECT_EQ(counts.occluded, c.counts.occluded) << c.name;
    EXPECT_EQ(counts.partial, c.counts.partial) << c.name;
  }
}

}  // namespace
}  // namespace facet::shadow_reference
