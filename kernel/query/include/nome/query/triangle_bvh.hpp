#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/query/display_triangles.hpp"
#include "nome/query/ray.hpp"

namespace nome {

// What a ray hit: a face's interior, one of its polygon edges, or one of its corners (decided exactly
// from the barycentric weights of the hit on a real polygon side; fan diagonals count as interior).
enum class ElementKind { face, edge, vertex };

// One crossing of the ray with the surface (libigl's unproject_onto_mesh result, with every hit kept:
// self-intersecting surfaces overlap).
struct RayHit {
  ElementKind kind = ElementKind::face;
  Index element = no_index;  // the face, edge or vertex id named by kind
  Index face = no_index;
  Index triangle = no_index;                   // index into DisplayTriangles
  std::array<double, 3> barycentric{0, 0, 0};  // weights of the triangle's three corners
  Vec3 point{0.0};                             // world position of the hit
  double depth = 0.0;                          // ray parameter t
};

// A BVH node: a box, and either a leaf's triangle range or the first of its two adjacent children.
struct BvhNode {
  Vec3 lower{0.0}, upper{0.0};
  Index first =
      0;  // leaf: first entry in the triangle order; inner: index of the left child (right = left + 1)
  Index count = 0;  // leaf: number of triangles; inner: 0
};

struct BvhOptions {
  Index max_leaf_size = 4;
  // From this many triangles on, the two halves of the tree are built on two threads.
  Index parallel_build_threshold = Index{1} << 16;
};

// Hits nearest first (equal depths ordered by face, then triangle), one per face and depth: a ray through
// a fan diagonal or a face's first corner crosses several triangles of one face at one point.
std::vector<RayHit> sorted_unique_hits(std::vector<RayHit> hits);

// A bounding volume hierarchy over the triangles a mesh is drawn with (display_triangles, shared with the
// renderer, so a pick lands on the triangle the user sees), for CPU picking. Built over the triangles sorted
// by Morton code (a linear BVH, Karras 2012): fast enough to build on every new topology.
// It copies the positions it needs, so it stays valid while the mesh it came from changes or dies;
// rebuild it when the displayed geometry changes.
class TriangleBvh {
 public:
  TriangleBvh() = default;
  TriangleBvh(const Mesh& mesh, const BvhOptions& options = {});

  // Every hit along the ray, nearest first (equal depths ordered by face). A face is reported once
  // per depth even when the ray crosses a fan diagonal.
  std::vector<RayHit> cast_all(const Ray& ray) const;
  // The nearest hit, if any.
  std::optional<RayHit> cast_nearest(const Ray& ray) const;

  Index num_triangles() const { return triangles_.size(); }
  Index num_nodes() const { return static_cast<Index>(nodes_.size()); }
  const DisplayTriangles& triangles() const { return triangles_; }
  // The mesh vertex at corner i (0..2) of triangle t, and its position as the tree stored it.
  Index triangle_vertex(Index t, int i) const { return corner_vertices_[triangles_.corners[t][i]]; }
  const Vec3& triangle_point(Index t, int i) const { return positions_[triangle_vertex(t, i)]; }

  // Calls visit(a, b) with the triangle ranges of every pair of leaves whose boxes overlap, a leaf with
  // itself included and each unordered pair once: the candidates of a self-intersection test, found by
  // descending the tree against itself. Pairs are dealt out to `parts` shares; this call does share `part`.
  template <typename Visit>
  void visit_overlapping_leaves(int part, int parts, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::vector<std::array<Index, 2>> pairs{{0, 0}}, next;
    // Breadth first until there are enough pairs to deal out evenly, then depth first per pair.
    while (pairs.size() < 64 * std::size_t(parts)) {
      next.clear();
      bool has_inner = false;
      for (const auto& pair : pairs) {
        if (split_pair(pair, next))
          has_inner = true;
        else
          next.push_back(pair);
      }
      pairs.swap(next);
      if (!has_inner) break;
    }
    std::vector<std::array<Index, 2>> stack;
    for (std::size_t i = std::size_t(part); i < pairs.size(); i += std::size_t(parts)) {
      stack.assign(1, pairs[i]);
      while (!stack.empty()) {
        const auto pair = stack.back();
        stack.pop_back();
        if (split_pair(pair, stack)) continue;
        if (!overlaps(pair[0], pair[1])) continue;
        const BvhNode &a = nodes_[pair[0]], &b = nodes_[pair[1]];
        visit(std::span<const Index>(order_.data() + a.first, a.count),
              std::span<const Index>(order_.data() + b.first, b.count));
      }
    }
  }

  // Calls visit(t) for each triangle in a leaf whose box overlaps [lower, upper]: a superset of the
  // triangles meeting that box, for proximity queries (the print check).
  template <typename Visit>
  void visit_box(const Vec3& lower, const Vec3& upper, Visit&& visit) const {
    if (nodes_.empty()) return;
    Index stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const BvhNode& node = nodes_[stack[--top]];
      if (node.lower.x > upper.x || node.lower.y > upper.y || node.lower.z > upper.z ||
          node.upper.x < lower.x || node.upper.y < lower.y || node.upper.z < lower.z)
        continue;
      if (node.count > 0) {
        for (Index i = node.first; i < node.first + node.count; ++i) visit(order_[i]);
      } else {
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      }
    }
  }

  // The classified hit of the ray on triangle t at the given triangle hit (shared with the
  // brute-force reference in the tests).
  RayHit make_hit(const Ray& ray, Index t, const TriangleHit& hit) const;
  // Tests one triangle (for brute force comparisons).
  bool intersect(const ShearedRay& ray, Index t, TriangleHit& hit) const;

 private:
  template <typename Visit>
  void traverse(const ShearedRay& ray, double& t_max, Visit&& visit) const;

  bool overlaps(Index a, Index b) const {
    const BvhNode &x = nodes_[a], &y = nodes_[b];
    return !(x.lower.x > y.upper.x || x.lower.y > y.upper.y || x.lower.z > y.upper.z ||
             y.lower.x > x.upper.x || y.lower.y > x.upper.y || y.lower.z > x.upper.z);
  }
  // For an overlapping pair of nodes with an inner node, adds the pairs of their children that may overlap
  // and returns true; returns false for a pair of leaves (or a leaf with itself), adding nothing.
  bool split_pair(const std::array<Index, 2>& pair, std::vector<std::array<Index, 2>>& out) const {
    const auto [a, b] = pair;
    const BvhNode &x = nodes_[a], &y = nodes_[b];
    if (x.count > 0 && y.count > 0) return false;
    if (!overlaps(a, b)) return true;
    if (a == b) {
      out.push_back({x.first, x.first});
      out.push_back({x.first + 1, x.first + 1});
      out.push_back({x.first, x.first + 1});
    } else if (y.count > 0 || (x.count == 0 && volume(x) >= volume(y))) {
      out.push_back({x.first, b});
      out.push_back({x.first + 1, b});
    } else {
      out.push_back({a, y.first});
      out.push_back({a, y.first + 1});
    }
    return true;
  }
  static double volume(const BvhNode& n) {
    const Vec3 d = n.upper - n.lower;
    return d.x * d.y * d.z + d.x + d.y + d.z;
  }

  DisplayTriangles triangles_;
  Buffer<Vec3> positions_;
  std::vector<Index> order_;  // triangle ids; leaves own contiguous ranges
  std::vector<BvhNode> nodes_;
  // Polygon structure for classifying hits on edges and corners.
  Buffer<Index> corner_vertices_;
  Buffer<Index> corner_edges_;
  std::vector<Index> corner_next_;
};

}  // namespace nome
