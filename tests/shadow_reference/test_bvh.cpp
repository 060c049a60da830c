// The BVH against brute force: every closest hit and every occlusion query of random rays in a
// random scene must equal the answer of testing every triangle, so a traversal that skips a
// node, visits children in the wrong order or stops early fails here.
#include <gtest/gtest.h>

#include <random>

#include "facet/shadow_reference/bvh.h"

namespace facet::shadow_reference {
namespace {

std::vector<WorldTriangle> randomTriangles(std::mt19937_64& rng, size_t count, uint32_t objects) {
  std::uniform_real_distribution<double> where(-10, 10), size(-1, 1);
  std::vector<WorldTriangle> out;
  for (size_t i = 0; i < count; ++i) {
    const glm::dvec3 c(where(rng), where(rng), where(rng));
    out.push_back({c + glm::dvec3(size(rng), size(rng), size(rng)), c + glm::dvec3(size(rng), size(rng), size(rng)),
                   c + glm::dvec3(size(rng), size(rng), size(rng)), uint32_t(i % objects)});
  }
  return out;
}

std::optional<Hit> bruteClosest(const std::vector<WorldTriangle>& triangles, Ray ray) {
  std::optional<Hit> best;
  for (size_t i = 0; i < triangles.size(); ++i)
    if (auto t = intersectTriangle(ray, triangles[i])) {
      best = Hit{*t, uint32_t(i)};
      ray.tMax = *t;
    }
  return best;
}

bool bruteOccluded(const std::vector<WorldTriangle>& triangles, const Ray& ray, const std::vector<bool>& blocks,
                   uint32_t ignored) {
  for (size_t i = 0; i < triangles.size(); ++i)
    if (blocks[triangles[i].object] && i != ignored && intersectTriangle(ray, triangles[i])) return true;
  return false;
}

TEST(ShadowBvh, MatchesBruteForceOnARandomScene) {
  std::mt19937_64 rng(7);
  const std::vector<WorldTriangle> triangles = randomTriangles(rng, 3000, 5);
  const Bvh bvh(triangles);
  const std::vector<bool> blocks{true, false, true, true, false};
  std::uniform_real_distribution<double> where(-12, 12), unit(-1, 1), length(5, 40);
  size_t hits = 0, occluded = 0;
  for (int r = 0; r < 4000; ++r) {
    Ray ray{{where(rng), where(rng), where(rng)}, {unit(rng), unit(rng), unit(rng)}, 0, length(rng)};
    if (r % 10 == 0) ray.direction = {0, r % 20 == 0 ? 1.0 : -1.0, 0};  // axis-aligned: zero components
    const std::optional<Hit> expected = bruteClosest(triangles, ray);
    const std::optional<Hit> actual = bvh.closestHit(ray);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << "ray " << r;
    if (expected) {
      ++hits;
      EXPECT_EQ(expected->triangle, actual->triangle) << "ray " << r;
      EXPECT_EQ(expected->t, actual->t) << "ray " << r;
    }
    const uint32_t ignored = expected ? expected->triangle : kNoTriangle;
    const bool blocked = bruteOccluded(triangles, ray, blocks, ignored);
    occluded += blocked;
    ASSERT_EQ(blocked, bvh.occluded(ray, blocks, ignored)) << "ray " << r;
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(hits, 800u);
  EXPECT_GT(occluded, 400u);
  EXPECT_LT(occluded, 3600u);
}

// Many triangles with one centroid (no split separates them) and a long row (the SAH peels them
// off one at a time): both must build, stay within the traversal stack and answer as brute force.
TEST(ShadowBvh, DegenerateLayoutsStayBoundedAndCorrect) {
  std::vector<WorldTriangle> same(500, WorldTriangle{{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}, 0});
  std::vector<WorldTriangle> row;
  for (int i = 0; i < 2000; ++i) {
    const double x = std::ldexp(1.0, i % 40) * 1e-6;  // exponentially spaced
    row.push_back({{x, 0, 0}, {x, 1, 0}, {x, 0, 1}, 0});
  }
  for (const auto* triangles : {&same, &row}) {
    const Bvh bvh(*triangles);
    EXPECT_LE(bvh.depth(), 80u);
    const Ray down{{0.1, 5, 0.1}, {0, -1, 0}, 0, 100};
    const Ray along{{-1, 0.25, 0.25}, {1, 0, 0}, 0, 1e7};
    for (const Ray& ray : {down, along}) {
      const std::optional<Hit> expected = bruteClosest(*triangles, ray), actual = bvh.closestHit(ray);
      ASSERT_EQ(expected.has_value(), actual.has_value());
      if (expected) {
        EXPECT_EQ(expected->t, actual->t);
      }
      EXPECT_EQ(bruteOccluded(*triangles, ray, {true}, kNoTriangle), bvh.occluded(ray, {true}));
    }
  }
}

// A ray through a vertex shared by a fan of triangles (the sphere mesh's pole) meets one of them
// despite rounding: the barycentric slack.
TEST(ShadowBvh, ARayThroughASharedVertexHits) {
  std::vector<WorldTriangle> fan;
  const int n = 128;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, b = 2 * M_PI * (i + 1) / n;
    fan.push_back(
        {{0.3, 1.7, 0.1}, {0.3 + std::cos(a), 1.6, 0.1 + std::sin(a)}, {0.3 + std::cos(b), 1.6, 0.1 + std::sin(b)}, 0});
  }
  const Bvh bvh(fan);
  EXPECT_TRUE(bvh.occluded({{0.3, 0, 0.1}, {0, 1, 0}, 0, 10}, {true}));
  ASSERT_TRUE(bvh.closestHit({{0.3, 0, 0.1}, {0, 1, 0}, 0, 10}).has_value());
}

TEST(ShadowBvh, EmptySceneHitsNothing) {
  const Bvh bvh({});
  EXPECT_FALSE(bvh.closestHit({{0, 0, 0}, {0, 1, 0}, 0, 10}).has_value());
  EXPECT_FALSE(bvh.occluded({{0, 0, 0}, {0, 1, 0}, 0, 10}, {}));
}

}  // namespace
}  // namespace facet::shadow_reference
