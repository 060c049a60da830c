// A bounding volume hierarchy over world triangles, for the CPU shadow reference: binned
// surface-area-heuristic splits (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007), double precision throughout, closest-hit and any-hit traversal.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/shadow_reference/world_triangles.h"

namespace facet::shadow_reference {

inline constexpr uint32_t kNoTriangle = UINT32_MAX;

// The points origin + t · direction for t in (tMin, tMax); direction need not be unit length
// (t is then in its units).
struct Ray {
  glm::dvec3 origin{0};
  glm::dvec3 direction{0, 0, 1};
  double tMin = 0;
  double tMax = 1e300;
};

struct Hit {
  double t = 0;
  uint32_t triangle = kNoTriangle;  // index into the triangles the Bvh was built from
};

// Where the ray meets the triangle (Möller and Trumbore, "Fast, Minimum Storage Ray/Triangle
// Intersection", 1997), either side, or nullopt. Barycentric coordinates are accepted down to
// −kBarycentricSlack: in double they carry a relative rounding error near 1e-16 times the
// triangle's conditioning, so a ray through a shared edge or vertex (the pole of the sphere
// mesh, a grid line of the plane) would otherwise slip between the triangles that share it. The
// slack grows each triangle by 1e-12 of its size, far below anything a renderer resolves.
inline constexpr double kBarycentricSlack = 1e-12;
std::optional<double> intersectTriangle(const Ray& ray, const WorldTriangle& triangle);

class Bvh {
 public:
  explicit Bvh(const std::vector<WorldTriangle>& triangles);

  // The nearest triangle the ray meets in (tMin, tMax).
  std::optional<Hit> closestHit(const Ray& ray) const;
  // Whether the ray meets, in (tMin, tMax), a triangle other than `ignored` whose object is
  // marked in `blocks` (indexed by WorldTriangle::object).
  bool occluded(const Ray& ray, const std::vector<bool>& blocks, uint32_t ignored = kNoTriangle) const;

  size_t nodeCount() const { return nodes_.size(); }
  // The largest depth of a leaf (the root's children are at depth 1): traversal keeps a stack of
  // at most this many nodes.
  uint32_t depth() const { return depth_; }

 private:
  struct Node {
    glm::dvec3 lo, hi;
    uint32_t first = 0;  // leaf: the first of its triangles in triangles_; inner: the right child
    uint32_t count = 0;  // leaf: its triangles; 0 for an inner node (its left child is the next node)
    uint32_t axis = 0;   // inner: the axis it was split on, to visit the near child first
  };
  template <typename Visit>
  void traverse(const Ray& ray, double* tMax, Visit&& visit) const;

  std::vector<Node> nodes_;
  std::vector<WorldTriangle> triangles_;  // in leaf order
  std::vector<uint32_t> original_;        // the caller's index of each triangle in triangles_
  uint32_t depth_ = 0;
};

}  // namespace facet::shadow_reference
