#include "facet/shadow_reference/bvh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include <glm/geometric.hpp>

namespace facet::shadow_reference {
namespace {

constexpr int kBins = 16;
// A node of this many triangles or fewer becomes a leaf when the SAH finds no cheaper split; one
// of more is always split (a leaf is tested triangle by triangle).
constexpr uint32_t kMaxLeafTriangles = 4;
// Below this depth, nodes are split at their median instead: each such split halves the node, so
// no leaf lies deeper than kMedianDepth + log2(triangles) <= kMedianDepth + 32, the fixed
// traversal stack's bound, whatever the SAH would have peeled off one triangle at a time.
constexpr uint32_t kMedianDepth = 48;
constexpr size_t kStackSize = kMedianDepth + 33;

// A slab test's far distance is rounded in three operations; scaling it by 1 + 4 ulp keeps a ray
// that meets a flat box (the plane's bounds have no height) from missing it by rounding (Ize,
// "Robust BVH Ray Traversal", 2013).
constexpr double kFarScale = 1 + 4 * std::numeric_limits<double>::epsilon();

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void grow(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  double halfArea() const {
    if (lo.x > hi.x) return 0;
    const glm::dvec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

Box bounds(const WorldTriangle& t) {
  Box b;
  b.grow(t.a);
  b.grow(t.b);
  b.grow(t.c);
  return b;
}

}  // namespace

std::optional<double> intersectTriangle(const Ray& ray, const WorldTriangle& triangle) {
  const glm::dvec3 e1 = triangle.b - triangle.a, e2 = triangle.c - triangle.a;
  const glm::dvec3 p = glm::cross(ray.direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0) return std::nullopt;  // the ray runs in the triangle's plane: it covers nothing
  const double inverse = 1 / det;
  const glm::dvec3 s = ray.origin - triangle.a;
  const double u = glm::dot(s, p) * inverse;
  if (u < -kBarycentricSlack || u > 1 + kBarycentricSlack) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(ray.direction, q) * inverse;
  if (v < -kBarycentricSlack || u + v > 1 + kBarycentricSlack) return std::nullopt;
  const double t = glm::dot(e2, q) * inverse;
  if (!(t > ray.tMin && t < ray.tMax)) return std::nullopt;
  return t;
}

Bvh::Bvh(const std::vector<WorldTriangle>& triangles) {
  const uint32_t n = uint32_t(triangles.size());
  if (n == 0) return;
  std::vector<Box> boxes(n);
  std::vector<glm::dvec3> centroids(n);
  for (uint32_t i = 0; i < n; ++i) {
    boxes[i] = bounds(triangles[i]);
    centroids[i] = (boxes[i].lo + boxes[i].hi) * 0.5;
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);

  // Depth first, so that an inner node's left child is the node after it; a node's index is
  // given when it is taken off the stack, and a right child writes its own into its parent.
  struct Task {
    uint32_t begin, end, depth;
    uint32_t parent;  // kNoTriangle for the root and for left children
  };
  std::vector<Task> tasks{{0, n, 0, kNoTriangle}};
  nodes_.reserve(2 * size_t(n));
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const uint32_t index = uint32_t(nodes_.size());
    if (task.parent != kNoTriangle) nodes_[task.parent].first = index;
    depth_ = std::max(depth_, task.depth);
    Box box, centroidBox;
    for (uint32_t i = task.begin; i < task.end; ++i) {
      box.grow(boxes[order[i]]);
      centroidBox.grow(centroids[order[i]]);
    }
    nodes_.push_back({box.lo, box.hi, task.begin, task.end - task.begin, 0});
    const uint32_t count = task.end - task.begin;
    const glm::dvec3 extent = centroidBox.hi - centroidBox.lo;
    const uint32_t axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    if (count <= 1 || (extent[axis] == 0 && count <= kMaxLeafTriangles)) continue;

    uint32_t middle = task.begin;
    if (task.depth < kMedianDepth && extent[axis] > 0) {
      // Binned SAH: cost of a split ∝ 1 + (A_left · N_left + A_right · N_right) / A (one box
      // test for the node against one triangle test per triangle), of a leaf ∝ N.
      std::array<Box, kBins> binBoxes;
      std::array<uint32_t, kBins> binCounts{};
      auto binOf = [&](uint32_t t) {
        const double f = (centroids[t][axis] - centroidBox.lo[axis]) / extent[axis];
        return std::min(kBins - 1, int(f * kBins));
      };
      for (uint32_t i = task.begin; i < task.end; ++i) {
        const int b = binOf(order[i]);
        binBoxes[size_t(b)].grow(boxes[order[i]]);
        ++binCounts[size_t(b)];
      }
      std::array<double, kBins> rightCost{};
      Box right;
      uint32_t rightCount = 0;
      for (int b = kBins - 1; b > 0; --b) {
        right.grow(binBoxes[size_t(b)]);
        rightCount += binCounts[size_t(b)];
        rightCost[size_t(b)] = right.halfArea() * rightCount;
      }
      Box left;
      uint32_t leftCount = 0;
      double bestCost = std::numeric_limits<double>::infinity();
      int bestBin = 0;
      for (int b = 1; b < kBins; ++b) {
        left.grow(binBoxes[size_t(b - 1)]);
        leftCount += binCounts[size_t(b - 1)];
        if (leftCount == 0 || leftCount == count) continue;
        const double cost = left.halfArea() * leftCount + rightCost[size_t(b)];
        if (cost < bestCost) {
          bestCost = cost;
          bestBin = b;
        }
      }
      const double area = box.halfArea();
      const double splitCost = area > 0 ? 1 + bestCost / area : count;
      if (bestBin == 0 || (count <= kMaxLeafTriangles && splitCost >= count)) {
        if (count <= kMaxLeafTriangles) continue;
      } else {
        middle = uint32_t(std::partition(order.begin() + task.begin, order.begin() + task.end,
                                         [&](uint32_t t) { return binOf(t) < bestBin; }) -
                          order.begin());
      }
    }
    if (middle == task.begin || middle == task.end) {
      middle = task.begin + count / 2;
      std::nth_element(order.begin() + task.begin, order.begin() + middle, order.begin() + task.end,
                       [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    }
    nodes_[index].count = 0;
    nodes_[index].axis = axis;
    tasks.push_back({middle, task.end, task.depth + 1, index});
    tasks.push_back({task.begin, middle, task.depth + 1, kNoTriangle});
  }
  triangles_.reserve(n);
  for (uint32_t i : order) triangles_.push_back(triangles[i]);
  original_ = std::move(order);
}

template <typename Visit>
void Bvh::traverse(const Ray& ray, double* tMax, Visit&& visit) const {
  if (nodes_.empty()) return;
  // A zero component becomes a tiny one of the same reach: 0 · ∞ in the slab test would be NaN.
  glm::dvec3 inverse;
  for (int k = 0; k < 3; ++k) inverse[k] = 1 / (ray.direction[k] != 0 ? ray.direction[k] : 1e-300);
  std::array<uint32_t, kStackSize> stack;
  size_t top = 0;
  uint32_t node = 0;
  while (true) {
    const Node& n = nodes_[node];
    const glm::dvec3 t0 = (n.lo - ray.origin) * inverse, t1 = (n.hi - ray.origin) * inverse;
    const glm::dvec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    const double enter = std::max({near.x, near.y, near.z, ray.tMin});
    const double leave = std::min({far.x, far.y, far.z, *tMax}) * kFarScale;
    if (enter <= leave) {
      if (n.count == 0) {
        uint32_t first = node + 1, second = n.first;
        if (ray.direction[int(n.axis)] < 0) std::swap(first, second);
        stack[top++] = second;
        node = first;
        continue;
      }
      for (uint32_t i = n.first; i < n.first + n.count; ++i)
        if (visit(i)) return;
    }
    if (top == 0) return;
    node = stack[--top];
  }
}

std::optional<Hit> Bvh::closestHit(const Ray& ray) const {
  double tMax = ray.tMax;
  uint32_t best = kNoTriangle;
  traverse(ray, &tMax, [&](uint32_t i) {
    Ray clipped = ray;
    clipped.tMax = tMax;
    if (auto t = intersectTriangle(clipped, triangles_[i])) {
      tMax = *t;
      best = i;
    }
    return false;
  });
  if (best == kNoTriangle) return std::nullopt;
  return Hit{tMax, original_[best]};
}

bool Bvh::occluded(const Ray& ray, const std::vector<bool>& blocks, uint32_t ignored) const {
  double tMax = ray.tMax;
  bool found = false;
  traverse(ray, &tMax, [&](uint32_t i) {
    const WorldTriangle& t = triangles_[i];
    if (!blocks[t.object] || original_[i] == ignored) return false;
    found = intersectTriangle(ray, t).has_value();
    return found;
  });
  return found;
}

}  // namespace facet::shadow_reference
