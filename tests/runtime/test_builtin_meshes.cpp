// The built-in meshes (runtime/mesh.h: sphere, plane, box) and scene objects' transforms
// (T · R · S, normals by the inverse-transpose): the meshes' winding, normals, tangent frames and
// UVs on the CPU, and rendered on both backends against a CPU ray cast of the same shapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "gltf_test_files.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

struct MeshVertex {
  glm::dvec3 p, n;
  glm::dvec2 uv;
  glm::dvec4 t;
};

MeshVertex vertexOf(const Mesh& mesh, uint32_t i) {
  // The stream's floats in Vertex's order (mesh.h): position 0, normal 3, uv0 6, uv1 8, colour 10,
  // tangent 14.
  const float* f = &mesh.vertices[size_t(i) * abi::kVertexFloats];
  return {{f[0], f[1], f[2]}, {f[3], f[4], f[5]}, {f[6], f[7]}, {f[14], f[15], f[16], f[17]}};
}

struct NamedMesh {
  const char* name;
  Mesh mesh;
  double minCos;  // how far a vertex normal may lean from its triangle's plane: 0 for flat faces,
                  // the sphere's facets span π/64 of latitude, so cos(π/64) ≈ 0.9988 at worst
};

std::vector<NamedMesh> builtinMeshes() {
  return {{"sphere", makeSphere(), 0.998}, {"plane", makePlane(), 1 - 1e-6}, {"box", makeBox(), 1 - 1e-6}};
}

}  // namespace

// Counter-clockwise front faces (as materials' culling assumes): every triangle's geometric normal
// cross(p1 − p0, p2 − p0) agrees with its vertices' normals, which are unit length; and the closed
// meshes enclose a positive volume (divergence theorem: Σ p0 · (p1 × p2) / 6 > 0 only if every
// face winds outward): the box exactly 1, the sphere the volume of its inscribed polyhedron.
TEST(BuiltinMeshes, TrianglesWindCounterClockwiseAroundOutwardNormals) {
  for (const NamedMesh& m : builtinMeshes()) {
    SCOPED_TRACE(m.name);
    ASSERT_EQ(m.mesh.indices.size() % 3, 0u);
    double volume = 0, area = 0, worst = 1;
    size_t degenerate = 0;
    for (size_t i = 0; i < m.mesh.indices.size(); i += 3) {
      const MeshVertex a = vertexOf(m.mesh, m.mesh.indices[i]), b = vertexOf(m.mesh, m.mesh.indices[i + 1]),
                       c = vertexOf(m.mesh, m.mesh.indices[i + 2]);
      volume += glm::dot(a.p, glm::cross(b.p, c.p)) / 6;
      const glm::dvec3 g = glm::cross(b.p - a.p, c.p - a.p);
      area += glm::length(g) / 2;
      if (glm::length(g) < 1e-9) {  // the sphere's pole rows: two corners at the pole
        ++degenerate;
        continue;
      }
      for (const MeshVertex* v : {&a, &b, &c}) {
        EXPECT_NEAR(glm::length(v->n), 1, 1e-6);
        worst = std::min(worst, glm::dot(glm::normalize(g), v->n));
      }
    }
    EXPECT_GE(worst, m.minCos);
    if (std::string(m.name) == "sphere") {
      EXPECT_EQ(degenerate, 2u * 128);
      EXPECT_NEAR(volume, 4 * M_PI / 3, 4 * M_PI / 3 * 2e-3);
    } else if (std::string(m.name) == "box") {
      EXPECT_EQ(degenerate, 0u);
      EXPECT_NEAR(volume, 1, 1e-6);
      EXPECT_NEAR(area, 6, 1e-5);
    } else {
      EXPECT_EQ(degenerate, 0u);
      EXPECT_NEAR(area, 1, 1e-6);
    }
  }
}

// The tangent frame mesh.h promises: t unit length, orthogonal to n, along ∂P/∂u; w = ±1 with
// w · cross(n, t) along ∂P/∂v (MikkTSpace's bitangent, as the normal-mapping chunk rebuilds it).
// ∂P/∂u and ∂P/∂v are each triangle's, from its positions and UVs.
TEST(BuiltinMeshes, TangentFramesFollowTheUvs) {
  for (const NamedMesh& m : builtinMeshes()) {
    SCOPED_TRACE(m.name);
    double worstU = 1, worstV = 1;
    for (size_t i = 0; i < m.mesh.indices.size(); i += 3) {
      const MeshVertex a = vertexOf(m.mesh, m.mesh.indices[i]), b = vertexOf(m.mesh, m.mesh.indices[i + 1]),
                       c = vertexOf(m.mesh, m.mesh.indices[i + 2]);
      const glm::dvec3 e1 = b.p - a.p, e2 = c.p - a.p;
      const glm::dvec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
      const double det = d1.x * d2.y - d2.x * d1.y;
      if (glm::length(glm::cross(e1, e2)) < 1e-9 || std::abs(det) < 1e-12) continue;
      const glm::dvec3 dpdu = glm::normalize((e1 * d2.y - e2 * d1.y) / det);
      const glm::dvec3 dpdv = glm::normalize((e2 * d1.x - e1 * d2.x) / det);
      for (const MeshVertex* v : {&a, &b, &c}) {
        const glm::dvec3 t(v->t);
        EXPECT_NEAR(glm::length(t), 1, 1e-6);
        EXPECT_NEAR(glm::dot(t, v->n), 0, 1e-6);
        EXPECT_EQ(std::abs(v->t.w), 1);
        worstU = std::min(worstU, glm::dot(t, dpdu));
        worstV = std::min(worstV, glm::dot(v->t.w * glm::cross(v->n, t), dpdv));
      }
    }
    // Flat faces: exact. The sphere: its vertex tangents are analytic, the triangle's derivatives
    // a chord's, which lean by up to half a facet (π/128 of longitude).
    EXPECT_GE(worstU, m.minCos);
    EXPECT_GE(worstV, m.minCos);
  }
}

// The plane spans x, z in [−0.5, 0.5] at y = 0 with uv = (x + 0.5, z + 0.5); each box vertex lies
// on its face (|p · n| = 0.5, the other coordinates within ±0.5) with uv in [0, 1]².
TEST(BuiltinMeshes, PlaneAndBoxSpanTheUnitSquareAndCube) {
  const Mesh plane = makePlane();
  ASSERT_EQ(plane.vertices.size(), size_t(65 * 65) * abi::kVertexFloats);
  for (uint32_t i = 0; i < 65 * 65; ++i) {
    const MeshVertex v = vertexOf(plane, i);
    EXPECT_EQ(v.p.y, 0);
    EXPECT_LE(std::max(std::abs(v.p.x), std::abs(v.p.z)), 0.5);
    EXPECT_EQ(v.n, glm::dvec3(0, 1, 0));
    EXPECT_NEAR(v.uv.x, v.p.x + 0.5, 1e-6);
    EXPECT_NEAR(v.uv.y, v.p.z + 0.5, 1e-6);
  }
  const Mesh box = makeBox();
  ASSERT_EQ(box.vertices.size(), size_t(6 * 17 * 17) * abi::kVertexFloats);
  glm::dvec3 normalSum(0);
  for (uint32_t i = 0; i < 6 * 17 * 17; ++i) {
    const MeshVertex v = vertexOf(box, i);
    normalSum += v.n;
    EXPECT_NEAR(glm::dot(v.p, v.n), 0.5, 1e-6);
    EXPECT_LE(std::max({std::abs(v.p.x), std::abs(v.p.y), std::abs(v.p.z)}), 0.5 + 1e-7);
    EXPECT_TRUE(v.uv.x >= 0 && v.uv.x <= 1 && v.uv.y >= 0 && v.uv.y <= 1);
  }
  EXPECT_EQ(normalSum, glm::dvec3(0));  // six faces, opposite in pairs, the same grid each
}

namespace {

// ---- Rendered against a CPU ray cast ------------------------------------------------------------

// A shape in its object space: the unit sphere, the plane (y = 0, x and z in ±0.5, seen from +y),
// the box (±0.5), or the test glTF quad (z = 0, x and y in ±1, seen from +z).
enum class Shape { Sphere, Plane, Box, Quad };

struct Placed {
  Shape shape;
  glm::dmat4 model;  // the object's T · R · S (and, for the quad, its node's translation)
};

struct Hit {
  double t = INFINITY;
  int object = -1, face = -1;
  glm::dvec3 normal{0};  // world, unit
  glm::dvec2 uv{0};      // what the mesh's uv0 is there (the sphere's is not checked)
  double noV = 0;
};

// The box faces' (right, up) as mesh.h describes them: uv = (p · right + 0.5, 0.5 − p · up).
const glm::dvec3 kBoxFaces[6][2] = {{{0, 0, -1}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, -1}},
                                    {{1, 0, 0}, {0, 0, 1}},  {{1, 0, 0}, {0, 1, 0}}, {{-1, 0, 0}, {0, 1, 0}}};

// Where the ray o + t·d first meets the shape, in object space (t is the world ray's parameter:
// the model matrix is affine). Single-sided shapes are met from their front only.
std::optional<Hit> intersect(Shape shape, glm::dvec3 o, glm::dvec3 d) {
  Hit h;
  glm::dvec3 n, p;
  if (shape == Shape::Sphere) {
    const double half = glm::dot(o, d) / glm::dot(d, d), c = (glm::dot(o, o) - 1) / glm::dot(d, d);
    if (half * half - c <= 0) return std::nullopt;
    h.t = -half - std::sqrt(half * half - c);
    n = o + h.t * d;
    h.face = 0;
  } else if (shape == Shape::Plane || shape == Shape::Quad) {
    const int axis = shape == Shape::Plane ? 1 : 2;
    const double extent = shape == Shape::Plane ? 0.5 : 1;
    if (d[axis] >= 0) return std::nullopt;
    h.t = -o[axis] / d[axis];
    p = o + h.t * d;
    for (int i = 0; i < 3; ++i)
      if (i != axis && std::abs(p[i]) > extent) return std::nullopt;
    n = glm::dvec3(0);
    n[axis] = 1;
    h.face = 0;
    h.uv = shape == Shape::Plane ? glm::dvec2(p.x + 0.5, p.z + 0.5) : glm::dvec2((p.x + 1) / 2, (p.y + 1) / 2);
  } else {
    double near = -INFINITY, far = INFINITY;
    int nearAxis = 0;
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0) {
        if (std::abs(o[i]) > 0.5) return std::nullopt;
        continue;
      }
      double a = (-0.5 - o[i]) / d[i], b = (0.5 - o[i]) / d[i];
      if (a > b) std::swap(a, b);
      if (a > near) near = a, nearAxis = i;
      far = std::min(far, b);
    }
    if (near > far || near <= 0) return std::nullopt;
    h.t = near;
    n = glm::dvec3(0);
    n[nearAxis] = d[nearAxis] < 0 ? 1 : -1;
    p = o + h.t * d;
    for (int f = 0; f < 6; ++f) {
      if (glm::cross(kBoxFaces[f][0], kBoxFaces[f][1]) != n) continue;
      h.face = f;
      h.uv = {glm::dot(p, kBoxFaces[f][0]) + 0.5, 0.5 - glm::dot(p, kBoxFaces[f][1])};
    }
  }
  if (h.t <= 0) return std::nullopt;
  h.normal = n;
  return h;
}

struct RayCaster {
  const Scene& scene;
  std::vector<Placed> objects;
  glm::dmat4 inverseViewProjection;

  RayCaster(const Scene& s, std::vector<Placed> placed) : scene(s), objects(std::move(placed)) {
    const Camera& cam = s.camera;
    inverseViewProjection = glm::inverse(
        glm::perspective(glm::radians(cam.fovYDegrees), double(s.width) / s.height, cam.nearPlane, cam.farPlane) *
        glm::lookAt(cam.position, cam.target, cam.up));
  }

  // The nearest hit through the point (x, y) of the image (pixel centres at + 0.5).
  Hit cast(double x, double y) const {
    glm::dvec4 a = inverseViewProjection * glm::dvec4(x / scene.width * 2 - 1, 1 - y / scene.height * 2, -1, 1);
    glm::dvec4 b = inverseViewProjection * glm::dvec4(x / scene.width * 2 - 1, 1 - y / scene.height * 2, 1, 1);
    const glm::dvec3 origin = glm::dvec3(a) / a.w, dir = glm::normalize(glm::dvec3(b) / b.w - origin);
    Hit nearest;
    for (size_t i = 0; i < objects.size(); ++i) {
      const glm::dmat4 inverse = glm::inverse(objects[i].model);
      auto h = intersect(objects[i].shape, glm::dvec3(inverse * glm::dvec4(origin, 1)),
                         glm::dvec3(inverse * glm::dvec4(dir, 0)));
      if (!h || h->t >= nearest.t) continue;
      nearest = *h;
      nearest.object = int(i);
      nearest.normal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(objects[i].model))) * h->normal);
      nearest.noV = -glm::dot(nearest.normal, dir);
    }
    return nearest;
  }

  // A pixel whose centre and the points 0.75 pixel around it see the same face of the same object
  // (so neither an edge nor a silhouette passes through it), and not at a grazing angle, where
  // the tessellated sphere's silhouette and the true one's differ.
  std::optional<Hit> interior(uint32_t x, uint32_t y) const {
    const Hit centre = cast(x + 0.5, y + 0.5);
    if (centre.object < 0 || centre.noV < 0.2) return std::nullopt;
    for (auto [dx, dy] : {std::pair{-0.75, 0.0}, {0.75, 0.0}, {0.0, -0.75}, {0.0, 0.75}}) {
      const Hit h = cast(x + 0.5 + dx, y + 0.5 + dy);
      if (h.object != centre.object || h.face != centre.face) return std::nullopt;
    }
    return centre;
  }
};

glm::dmat4 trs(glm::dvec3 position, glm::dmat4 rotation, glm::dvec3 scale) {
  return glm::translate(glm::dmat4(1), position) * rotation * glm::scale(glm::dmat4(1), scale);
}

// Euler degrees as docs/scene-format.md defines them: about x, then y, then z (world axes).
glm::dmat4 euler(double x, double y, double z) {
  const auto about = [](double degrees, glm::dvec3 axis) {
    return glm::rotate(glm::dmat4(1), glm::radians(degrees), axis);
  };
  return about(z, {0, 0, 1}) * about(y, {0, 1, 0}) * about(x, {1, 0, 0});
}

// Every mesh, rotated and non-uniformly scaled: the plane (a ground turned 10°), two boxes (one
// turned about y, one about all three axes), a squashed sphere turned by a quaternion, and the glTF
// quad whose node moves it 0.5 along x before the object's transform applies.
const char* kShapesScene = R"({"width": 160, "height": 120,
  "camera": {"position": [2.2, 2.6, 4.5], "target": [0, 0.4, 0], "fovY": 45},
  "objects": [
    {"mesh": "plane", "material": "%s", "scale": [6, 1, 5], "rotation": [0, 10, 0]},
    {"mesh": "box", "material": "%s", "position": [-1.0, 0.5, 0.2], "scale": [0.9, 1.0, 0.6], "rotation": [0, 30, 0]},
    {"mesh": "box", "material": "%s", "position": [1.3, 0.8, -0.4], "scale": [0.5, 0.7, 0.9], "rotation": [25, 40, 15]},
    {"mesh": "sphere", "material": "%s", "position": [0.2, 0.9, 1.0], "scale": [0.9, 0.45, 0.6],
     "quaternion": [0.2, 0.3, 0.1, 0.9]},
    {"mesh": "quad.gltf", "material": "%s", "position": [-0.2, 1.2, -2.0], "scale": [0.6, 0.4, 1], "rotation": [0, -20, 0]}
  ]})";

std::vector<Placed> shapesPlaced() {
  // [0.2, 0.3, 0.1, 0.9] as an angle about an axis (normalised: the scene reader's contract).
  const glm::dvec4 q = glm::normalize(glm::dvec4(0.2, 0.3, 0.1, 0.9));
  const glm::dmat4 quaternion = glm::rotate(glm::dmat4(1), 2 * std::acos(q.w), glm::normalize(glm::dvec3(q)));
  return {{Shape::Plane, trs({0, 0, 0}, euler(0, 10, 0), {6, 1, 5})},
          {Shape::Box, trs({-1.0, 0.5, 0.2}, euler(0, 30, 0), {0.9, 1.0, 0.6})},
          {Shape::Box, trs({1.3, 0.8, -0.4}, euler(25, 40, 15), {0.5, 0.7, 0.9})},
          {Shape::Sphere, trs({0.2, 0.9, 1.0}, quaternion, {0.9, 0.45, 0.6})},
          {Shape::Quad, trs({-0.2, 1.2, -2.0}, euler(0, -20, 0), {0.6, 0.4, 1}) *
                            glm::translate(glm::dmat4(1), glm::dvec3(0.5, 0, 0))}};
}

struct ShapesRender {
  std::string error;
  Scene scene;
  FrameResult vulkan, gl;
  std::vector<std::string> validation;
};

// The scene rendered with an unlit material showing `show` (an expression of vertex inputs, each
// component in [0, 1]) on both backends.
ShapesRender renderShapes(const std::string& show) {
  ShapesRender out;
  const std::string packages =
      test::writePackagesFromTexts("builtin-meshes-" + std::to_string(std::hash<std::string>()(show)),
                                   {"material show { shading unlit\n surface { baseColor = " + show + " } }"});
  const std::string dir = test::scratchDir("builtin-meshes-scene");
  test::writeQuad(dir, "quad.bin",
                  R"("nodes": [{"mesh": 0, "translation": [0.5, 0, 0]}], "scenes": [{"nodes": [0]}], "scene": 0)");
  char json[2048];
  std::snprintf(json, sizeof json, kShapesScene, "show", "show", "show", "show", "show");
  auto scene = parseScene(dir + "/shapes.json", json, &out.error);
  if (!scene) return out;
  out.scene = *scene;
  auto frame = SceneFrame::prepare(*scene, packages, &out.error);
  if (!frame) return out;
  auto vk = createVulkanBackend({true}, &out.error);
  if (!vk || !vk->render(frame->frame(), &out.vulkan, &out.error)) return out;
  auto gl = createGlBackend(&out.error);
  if (!gl || !gl->render(frame->frame(), &out.gl, &out.error)) return out;
  for (const auto& m : vk->validationErrors()) out.validation.push_back("Vulkan validation: " + m);
  for (const auto& m : gl->validationErrors()) out.validation.push_back("GL debug output: " + m);
  return out;
}

// Compares every interior pixel (RayCaster::interior) of both backends' HDR images with
// `expected(hit)`, per channel within `tolerance`; returns the largest difference seen.
template <typename Expected>
double compareWithRayCast(const ShapesRender& r, Expected expected, double tolerance, size_t* checkedPerObject) {
  const RayCaster caster(r.scene, shapesPlaced());
  double worst = 0;
  for (uint32_t y = 0; y < r.scene.height; ++y) {
    for (uint32_t x = 0; x < r.scene.width; ++x) {
      const std::optional<Hit> hit = caster.interior(x, y);
      if (!hit) continue;
      const glm::dvec3 want = expected(*hit);
      if (want.x < 0) continue;  // not checked
      ++checkedPerObject[hit->object];
      for (const FrameResult* image : {&r.vulkan, &r.gl}) {
        const float* got = &image->hdr[(size_t(y) * r.scene.width + x) * 4];
        for (int c = 0; c < 3; ++c) {
          const double d = std::abs(got[c] - want[c]);
          worst = std::max(worst, d);
          if (d > tolerance) {
            ADD_FAILURE() << (image == &r.vulkan ? "Vulkan" : "GL") << " pixel (" << x << ", " << y << ") object "
                          << hit->object << " face " << hit->face << " channel " << c << ": " << got[c] << ", want "
                          << want[c];
            return worst;
          }
        }
      }
    }
  }
  return worst;
}

}  // namespace

// Each pixel's interpolated world normal (shown as n · 0.5 + 0.5) is the analytic shape's normal
// there: the inverse-transpose of the model matrix keeps normals perpendicular to the squashed
// sphere and the scaled boxes (with the model matrix itself the sphere's pixels are 0.10 off).
// Tolerance 0.01 (0.02 of a normal component): measured worst 0.0017, from the sphere's facets
// (interpolated between exact vertex normals) and fp16's steps of 1/2048 near 1.
TEST(BuiltinMeshes, RenderedNormalsMatchTheAnalyticShapesOnBothBackends) {
  const ShapesRender r = renderShapes("vertex.normal * 0.5 + 0.5");
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.validation, std::vector<std::string>{});
  size_t checked[5] = {};
  const double worst = compareWithRayCast(
      r, [](const Hit& h) { return h.normal * 0.5 + 0.5; }, 0.01, checked);
  std::printf("normals: worst difference %.5f; pixels checked per object %zu %zu %zu %zu %zu\n", worst, checked[0],
              checked[1], checked[2], checked[3], checked[4]);
  for (size_t n : checked) EXPECT_GT(n, 100u);
}

// uv0 (shown as (u, v, 0)) is where mesh.h puts it on the plane, on each box face and on the glTF
// quad: linear over each face (interpolated perspective-correctly), so within fp16's steps.
TEST(BuiltinMeshes, RenderedUvsMatchTheirDescriptionOnBothBackends) {
  const ShapesRender r = renderShapes("vec3(vertex.uv0, 0.0)");
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.validation, std::vector<std::string>{});
  size_t checked[5] = {};
  const double worst = compareWithRayCast(
      r, [](const Hit& h) { return h.object == 3 ? glm::dvec3(-1) : glm::dvec3(h.uv, 0); }, 0.004, checked);
  std::printf("uvs: worst difference %.5f\n", worst);
  for (size_t object : {0, 1, 2, 4}) EXPECT_GT(checked[object], 100u) << object;
}

}  // namespace facet::runtime

namespace facet::runtime {

// The plane's tessellation is what the mid tier's per-vertex diffuse needs (mesh.h): a 20 m ground
// lit by a point light 1.25 m above it, drawn with the mid tier's per-vertex diffuse and with the
// same material's per-pixel diffuse (`tier mid { diffuse = pixel }`), differs by at most 5 % of
// the brightest pixel (mesh.h's bound: (3/4)(Δ/h)² = 4.7 %). The material has no specular
// (reflectance 0, roughness 1, no ambient), so the two differ only in where diffuse is evaluated
// (with 512 segments they agree within 0.2 %). The same plane with 16 segments (Δ = 1.25 m) fails.
TEST(BuiltinMeshes, PlaneIsFineEnoughForPerVertexPointLights) {
  compiler::BuildOptions build;
  build.pointLightCounts = {0, 1};
  const std::string surface =
      "param c: color = vec3(0.8, 0.8, 0.8)\n surface { baseColor = params.c\n"
      " roughness = 1.0\n reflectance = 0.0 } }";
  const std::string packages = test::writePackagesFromTexts(
      "plane-vertex-lighting",
      {"material per_vertex { " + surface, "material per_pixel { tier mid { diffuse = pixel }\n" + surface}, build);
  const auto sceneWith = [](const char* material) {
    return std::string(R"({"width": 128, "height": 128, "tier": "mid",
      "camera": {"position": [0, 8, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 60,
                 "aperture": 2.8, "shutter": 0.033, "iso": 800},
      "lights": [{"type": "point", "position": [0.3, 1.25, 0.2], "intensity": 40, "range": 100}],
      "objects": [{"mesh": "plane", "material": ")") +
           material + R"(", "scale": [20, 1, 20]}]})";
  };
  std::string error;
  auto vk = createVulkanBackend({true}, &error);
  auto gl = createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  const Mesh coarse = makePlane(16);
  for (RenderBackend* backend : {vk.get(), gl.get()}) {
    SCOPED_TRACE(backend->name());
    std::vector<FrameResult> images;
    for (const char* material : {"per_pixel", "per_vertex", "per_vertex_coarse"}) {
      const bool coarsen = std::string(material) == "per_vertex_coarse";
      auto scene = parseScene("plane.json", sceneWith(coarsen ? "per_vertex" : material), &error);
      ASSERT_TRUE(scene) << error;
      auto frame = SceneFrame::prepare(*scene, packages, &error);
      ASSERT_TRUE(frame) << error;
      FrameDesc desc = frame->frame();
      if (coarsen) desc.draws.at(0).mesh = &coarse;
      images.emplace_back();
      ASSERT_TRUE(backend->render(desc, &images.back(), &error)) << error;
    }
    const auto worstShare = [&](const FrameResult& got) {  // of the colour channels (alpha is 1)
      double peak = 0, worst = 0;
      for (size_t i = 0; i < images[0].hdr.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max<double>(peak, images[0].hdr[i]);
        worst = std::max<double>(worst, std::abs(got.hdr[i] - images[0].hdr[i]));
      }
      return worst / peak;
    };
    std::printf("%s: per-vertex against per-pixel diffuse, worst %.4f of the peak (64 segments), %.4f (16)\n",
                backend->name(), worstShare(images[1]), worstShare(images[2]));
    EXPECT_LE(worstShare(images[1]), 0.05);
    EXPECT_GT(worstShare(images[2]), 0.1);
    EXPECT_TRUE(backend->validationErrors().empty());
  }
}

}  // namespace facet::runtime
