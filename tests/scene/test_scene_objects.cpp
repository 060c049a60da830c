// A scene object's mesh and transform as the scene file gives them (docs/scene-format.md,
// "Transforms"): what each form means, and each wrong value ending in an error at its JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <string>

#include "facet/scene/scene.h"

namespace {

using facet::runtime::parseScene;
using facet::runtime::SceneObject;

// The scene's one object, given as the text inside its braces.
SceneObject objectOf(const std::string& fields) {
  std::string error;
  auto scene = parseScene("s.json", R"({"objects": [{"material": "m", )" + fields + "}]}", &error);
  EXPECT_TRUE(scene) << error;
  return scene ? scene->objects.at(0) : SceneObject{};
}

std::string errorOf(const std::string& fields) {
  std::string error;
  EXPECT_FALSE(parseScene("s.json", R"({"objects": [{"material": "m", )" + fields + "}]}", &error))
      << "accepted: " << fields;
  return error;
}

void expectNear(const glm::dvec3& got, const glm::dvec3& want, const char* what) {
  EXPECT_LT(glm::length(got - want), 1e-12) << what << ": (" << got.x << ", " << got.y << ", " << got.z << ")";
}

}  // namespace

TEST(SceneObjects, DefaultsAreTheUnitSphereUnrotated) {
  SceneObject o = objectOf(R"("position": [1, 2, 3])");
  EXPECT_EQ(o.mesh, "sphere");
  EXPECT_EQ(o.radius, 1);
  EXPECT_EQ(o.scale, glm::dvec3(1));
  EXPECT_EQ(o.rotation, glm::dquat(1, 0, 0, 0));
  EXPECT_EQ(objectOf(R"("mesh": "plane")").mesh, "plane");
  EXPECT_EQ(objectOf(R"("mesh": "box")").mesh, "box");
}

// Degrees about the world axes, x first, then y, then z, counter-clockwise looking down each axis
// towards the origin: 90° about z takes +x to +y; [90, 90, 0] takes +y first to +z (about x),
// then +z to +x (about y).
TEST(SceneObjects, EulerDegreesTurnAboutWorldAxesXThenYThenZ) {
  expectNear(objectOf(R"("rotation": [0, 0, 90])").rotation * glm::dvec3(1, 0, 0), {0, 1, 0}, "z 90");
  expectNear(objectOf(R"("rotation": [90, 0, 0])").rotation * glm::dvec3(0, 1, 0), {0, 0, 1}, "x 90");
  expectNear(objectOf(R"("rotation": [0, 90, 0])").rotation * glm::dvec3(0, 0, 1), {1, 0, 0}, "y 90");
  const glm::dquat xy = objectOf(R"("rotation": [90, 90, 0])").rotation;
  expectNear(xy * glm::dvec3(0, 1, 0), {1, 0, 0}, "x then y");
  expectNear(xy * glm::dvec3(1, 0, 0), {0, 0, -1}, "x then y, +x");  // x keeps +x, y takes it to −z
}

// glTF's order [x, y, z, w], normalised: [0, 1, 0, 1] is 90° about y, as [0, 90, 0].
TEST(SceneObjects, QuaternionIsXyzwAndNormalised) {
  const glm::dquat q = objectOf(R"("quaternion": [0, 1, 0, 1])").rotation;
  EXPECT_NEAR(glm::length(q), 1, 1e-15);
  expectNear(q * glm::dvec3(0, 0, 1), {1, 0, 0}, "quaternion");
  const glm::dquat e = objectOf(R"("rotation": [0, 90, 0])").rotation;
  EXPECT_NEAR(std::abs(glm::dot(q, e)), 1, 1e-12);
}

TEST(SceneObjects, ScaleIsANumberOrPerAxis) {
  EXPECT_EQ(objectOf(R"("scale": 2.5)").scale, glm::dvec3(2.5));
  EXPECT_EQ(objectOf(R"("mesh": "box", "scale": [0.1, 3, 0.2])").scale, glm::dvec3(0.1, 3, 0.2));
  EXPECT_EQ(objectOf(R"("scale": [0.1, 3, 0.2])").radius, 1);
  EXPECT_EQ(objectOf(R"("radius": 0.4)").scale, glm::dvec3(1));
}

TEST(SceneObjects, UnknownMeshListsTheBuiltInOnes) {
  EXPECT_EQ(errorOf(R"("mesh": "cube")"),
            "s.json: error: /objects/0/mesh: unknown mesh 'cube' (built in: sphere, plane, box; or a .gltf/.glb file)");
  EXPECT_EQ(errorOf(R"("mesh": 3)"), "s.json: error: /objects/0/mesh: expected a string");
}

TEST(SceneObjects, ZeroNegativeAndHugeScalesAreErrors) {
  EXPECT_EQ(errorOf(R"("scale": 0)"),
            "s.json: error: /objects/0/scale: a scale of 0 flattens the object; give a scale > 0");
  EXPECT_EQ(errorOf(R"("scale": [1, 0.0, 1])"),
            "s.json: error: /objects/0/scale/1: a scale of 0 flattens the object; give a scale > 0");
  EXPECT_EQ(errorOf(R"("scale": [1, 1, -2])"),
            "s.json: error: /objects/0/scale/2: a negative scale (-2) would mirror the object; mirroring is not "
            "supported, give a scale > 0");
  EXPECT_EQ(errorOf(R"("scale": [1, 1e-5, 1])"),
            "s.json: error: /objects/0/scale/1: value 1e-05 is outside [0.0001, 1000000.0]");
  EXPECT_EQ(errorOf(R"("scale": 1e300)"),
            "s.json: error: /objects/0/scale: value 1e+300 is outside [0.0001, 1000000.0]");
  // JSON has no infinity: an overflowing literal stops at the parser, with its line and column.
  EXPECT_EQ(errorOf(R"("scale": [1, 1e999, 1])"), "s.json:1:45: error: invalid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(errorOf(R"("scale": [1, 2])"), "s.json: error: /objects/0/scale: expected a number or [x, y, z]");
  EXPECT_EQ(errorOf(R"("scale": "big")"), "s.json: error: /objects/0/scale: expected a number or [x, y, z]");
  EXPECT_EQ(errorOf(R"("radius": 2, "scale": 2)"),
            "s.json: error: /objects/0/scale: give either 'radius' (a uniform scale) or 'scale', not both");
}

TEST(SceneObjects, MalformedRotationsAreErrors) {
  EXPECT_EQ(errorOf(R"("rotation": [0, 0, 0, 1])"),
            "s.json: error: /objects/0/rotation: expected [x, y, z]: angles in degrees about the x, y and z axes (a "
            "quaternion goes in 'quaternion')");
  EXPECT_EQ(errorOf(R"("rotation": 45)"),
            "s.json: error: /objects/0/rotation: expected [x, y, z]: angles in degrees about the x, y and z axes (a "
            "quaternion goes in 'quaternion')");
  EXPECT_EQ(errorOf(R"("rotation": [0, "90", 0])"), "s.json: error: /objects/0/rotation/1: expected a number");
  EXPECT_EQ(errorOf(R"("rotation": [0, 720, 0])"),
            "s.json: error: /objects/0/rotation/1: value 720 is outside [-360.0, 360.0]");
  EXPECT_EQ(errorOf(R"("quaternion": [0, 0, 0, 0])"),
            "s.json: error: /objects/0/quaternion: a quaternion needs a length of at least 1e-6 to be normalised");
  EXPECT_EQ(errorOf(R"("quaternion": [0, 1e-300, 0, 0])"),
            "s.json: error: /objects/0/quaternion: a quaternion needs a length of at least 1e-6 to be normalised");
  EXPECT_EQ(errorOf(R"("quaternion": [0, 0, 1])"),
            "s.json: error: /objects/0/quaternion: expected [x, y, z, w]: a quaternion");
  EXPECT_EQ(errorOf(R"("quaternion": [0, 0, 1, null])"), "s.json: error: /objects/0/quaternion/3: expected a number");
  EXPECT_EQ(errorOf(R"("rotation": [0, 0, 0], "quaternion": [0, 0, 0, 1])"),
            "s.json: error: /objects/0/quaternion: give either 'rotation' (degrees) or 'quaternion', not both");
}
