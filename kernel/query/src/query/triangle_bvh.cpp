#include "nome/query/triangle_bvh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <thread>
#include <utility>

#include "nome/thread_support.hpp"

namespace nome {
namespace {

// An axis-aligned box in double, as the nodes store it: it holds its triangles exactly.
struct Box {
  Vec3 lower{std::numeric_limits<double>::infinity()};
  Vec3 upper{-std::numeric_limits<double>::infinity()};

  void grow(const Vec3& p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void grow(const Box& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
};

// A triangle's corner positions, looked up where needed: storing a box per triangle costs more in
// page faults for a million triangles than the lookups do.
struct TrianglePoints {
  std::span<const Vec3> positions;
  std::span<const Index> corner_vertices;
  const DisplayTriangles& triangles;

  const Vec3& operator()(Index t, int corner) const {
    return positions[corner_vertices[triangles.corners[t][corner]]];
  }
  Vec3 centroid(Index t) const { return ((*this)(t, 0) + (*this)(t, 1) + (*this)(t, 2)) / 3.0; }
};

// Slab test widened by PBRT's 1 + 2 gamma(3) so rounding never drops a triangle lying on a box face.
// A zero direction component gives infinite reciprocals; a NaN from 0 * inf fails both comparisons
// and so leaves the interval unchanged, which is the conservative answer.
inline bool ray_hits_box(const Vec3& lower, const Vec3& upper, const Vec3& origin, const Vec3& inverse,
                         double t_min, double t_max, double& entry) {
  constexpr double eps = std::numeric_limits<double>::epsilon() * 0.5;
  constexpr double widen = 1.0 + 2.0 * (3.0 * eps) / (1.0 - 3.0 * eps);
  for (int axis = 0; axis < 3; ++axis) {
    double t0 = (lower[axis] - origin[axis]) * inverse[axis];
    double t1 = (upper[axis] - origin[axis]) * inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    t1 *= widen;
    if (t0 > t_min) t_min = t0;
    if (t1 < t_max) t_max = t1;
    if (t_min > t_max) return false;
  }
  entry = t_min;
  return true;
}

// Morton codes: 10 bits per axis of the triangle's centroid in a box around all of them, so that
// sorting by code puts triangles near each other in space next to each other in memory (Karras 2012).
constexpr int morton_bits = 10;

std::uint32_t spread_bits(std::uint32_t x) {
  x = (x | (x << 16)) & 0x030000FFu;
  x = (x | (x << 8)) & 0x0300F00Fu;
  x = (x | (x << 4)) & 0x030C30C3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

std::uint32_t morton_code(const Vec3& centroid, const Box& grid) {
  const Vec3 extent = grid.upper - grid.lower;
  std::uint32_t code = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double cells = double(1 << morton_bits);
    const double x = extent[axis] > 0.0 ? (centroid[axis] - grid.lower[axis]) / extent[axis] * cells : 0.0;
    const auto cell = std::uint32_t(std::clamp(x, 0.0, cells - 1.0));
    code |= spread_bits(cell) << (2 - axis);
  }
  return code;
}

// Keys are (code << 32 | triangle); a stable LSD radix sort on the code's bits keeps equal codes in
// triangle order, so the tree does not depend on the sort.
void sort_by_code(std::vector<std::uint64_t>& keys) {
  constexpr int digit_bits = morton_bits;
  constexpr std::uint64_t digit_mask = (1u << digit_bits) - 1;
  std::vector<std::uint64_t> sorted(keys.size());
  for (int shift = 32; shift < 32 + 3 * morton_bits; shift += digit_bits) {
    std::vector<Index> offsets((1u << digit_bits) + 1, 0);
    for (const std::uint64_t k : keys) ++offsets[((k >> shift) & digit_mask) + 1];
    for (std::size_t d = 1; d < offsets.size(); ++d) offsets[d] += offsets[d - 1];
    for (const std::uint64_t k : keys) sorted[offsets[(k >> shift) & digit_mask]++] = k;
    keys.swap(sorted);
  }
}

// Builds a subtree over keys[begin, end) (sorted by code) into `nodes`, its root first and each node's
// children adjacent. A node splits where the highest bit that differs between its first and last code
// changes (a spatial median), or in the middle when all its codes are equal. Returns the node's box.
class SubtreeBuilder {
 public:
  SubtreeBuilder(const std::vector<std::uint64_t>& keys, const TrianglePoints& points, Index max_leaf_size,
                 std::vector<BvhNode>& nodes)
      : keys_(keys), points_(points), max_leaf_size_(std::max<Index>(1, max_leaf_size)), nodes_(nodes) {}

  Box build(Index begin, Index end) {
    nodes_.reserve(nodes_.size() + 2 * ((end - begin) / max_leaf_size_) + 1);
    nodes_.push_back(BvhNode{});
    return build_node(Index(nodes_.size() - 1), begin, end);
  }

  // Where a node over keys[begin, end) splits, or none for a leaf.
  static std::optional<Index> split(const std::vector<std::uint64_t>& keys, Index begin, Index end,
                                    Index max_leaf_size) {
    if (end - begin <= max_leaf_size) return std::nullopt;
    const std::uint64_t differing = (keys[begin] ^ keys[end - 1]) >> 32;
    if (differing == 0) return begin + (end - begin) / 2;
    const int bit = 63 - std::countl_zero(differing) + 32;
    const auto first_set = std::partition_point(keys.begin() + begin, keys.begin() + end,
                                                [bit](std::uint64_t k) { return ((k >> bit) & 1u) == 0; });
    return Index(first_set - keys.begin());
  }

 private:
  Box build_node(Index node, Index begin, Index end) {
    Box box;
    const auto mid = split(keys_, begin, end, max_leaf_size_);
    if (!mid) {
      for (Index i = begin; i < end; ++i)
        for (int corner = 0; corner < 3; ++corner) box.grow(points_(Index(keys_[i]), corner));
      nodes_[node].first = begin;
      nodes_[node].count = end - begin;
    } else {
      const Index left = Index(nodes_.size());
      nodes_.push_back(BvhNode{});
      nodes_.push_back(BvhNode{});
      box = build_node(left, begin, *mid);
      box.grow(build_node(left + 1, *mid, end));
      nodes_[node].first = left;
      nodes_[node].count = 0;
    }
    nodes_[node].lower = box.lower;
    nodes_[node].upper = box.upper;
    return box;
  }

  const std::vector<std::uint64_t>& keys_;
  const TrianglePoints& points_;
  Index max_leaf_size_;
  std::vector<BvhNode>& nodes_;
};

constexpr int traversal_stack_size = 128;

bool hit_before(const RayHit& a, const RayHit& b) {
  if (a.depth != b.depth) return a.depth < b.depth;
  if (a.face != b.face) return a.face < b.face;
  return a.triangle < b.triangle;
}

}  // namespace

std::vector<RayHit> sorted_unique_hits(std::vector<RayHit> hits) {
  std::sort(hits.begin(), hits.end(), hit_before);
  // Depths of one point computed from different triangles may differ in the last bits.
  std::vector<RayHit> unique;
  unique.reserve(hits.size());
  for (const RayHit& h : hits) {
    const bool repeated = std::any_of(unique.rbegin(), unique.rend(), [&](const RayHit& u) {
      return u.face == h.face && std::abs(u.depth - h.depth) <= 1e-9 * std::max(1.0, std::abs(h.depth));
    });
    if (!repeated) unique.push_back(h);
  }
  return unique;
}

TriangleBvh::TriangleBvh(const Mesh& mesh, const BvhOptions& options)
    : triangles_(display_triangles(mesh)),
      positions_(mesh.positions()),
      corner_vertices_(mesh.corner_vertices()),
      corner_edges_(mesh.corner_edges()) {
  corner_next_.resize(mesh.num_corners());
  for (Index c = 0; c < mesh.num_corners(); ++c) corner_next_[c] = mesh.next_corner(c);

  const Index n = num_triangles();
  if (n == 0) return;
  const TrianglePoints points{positions_, corner_vertices_, triangles_};
  // The Morton grid spans the vertices' box, which holds every centroid (one pass, over contiguous data).
  Box bounds;
  for (const Vec3& p : positions_) bounds.grow(p);
  std::vector<std::uint64_t> keys(n);
  for (Index t = 0; t < n; ++t) keys[t] = std::uint64_t(morton_code(points.centroid(t), bounds)) << 32 | t;
  sort_by_code(keys);

  // The two halves of a large mesh are built on two threads (the machine we target has two cores), or one
  // after the other where threads cannot start: the same nodes.
  const auto mid = SubtreeBuilder::split(keys, 0, n, options.max_leaf_size);
  if (n >= options.parallel_build_threshold && mid) {
    std::vector<BvhNode> left, right;
    Box right_box;
    const auto build_right = [&] {
      right_box = SubtreeBuilder(keys, points, options.max_leaf_size, right).build(*mid, n);
    };
    std::thread worker;
    if (can_start_threads())
      worker = std::thread(build_right);
    else
      build_right();
    Box box = SubtreeBuilder(keys, points, options.max_leaf_size, left).build(0, *mid);
    if (worker.joinable()) worker.join();
    box.grow(right_box);
    // Root, the two subtree roots, then the rest of each subtree; inner nodes' child ids shift.
    nodes_.reserve(1 + left.size() + right.size());
    BvhNode top;
    top.lower = box.lower;
    top.upper = box.upper;
    top.first = 1;
    nodes_.push_back(top);
    const Index left_shift = 2, right_shift = 2 + Index(left.size()) - 1;
    auto shifted = [](BvhNode node, Index shift) {
      if (node.count == 0) node.first += shift;
      return node;
    };
    nodes_.push_back(shifted(left[0], left_shift));
    nodes_.push_back(shifted(right[0], right_shift));
    for (std::size_t i = 1; i < left.size(); ++i) nodes_.push_back(shifted(left[i], left_shift));
    for (std::size_t i = 1; i < right.size(); ++i) nodes_.push_back(shifted(right[i], right_shift));
  } else {
    SubtreeBuilder(keys, points, options.max_leaf_size, nodes_).build(0, n);
  }
  order_.resize(n);
  for (Index i = 0; i < n; ++i) order_[i] = Index(keys[i]);
}

bool TriangleBvh::intersect(const ShearedRay& ray, Index t, TriangleHit& hit) const {
  const auto& c = triangles_.corners[t];
  return intersect_triangle(ray, positions_[corner_vertices_[c[0]]], positions_[corner_vertices_[c[1]]],
                            positions_[corner_vertices_[c[2]]], hit);
}

RayHit TriangleBvh::make_hit(const Ray& ray, Index t, const TriangleHit& hit) const {
  RayHit out;
  out.face = triangles_.faces[t];
  out.triangle = t;
  out.barycentric = hit.barycentric;
  out.depth = hit.depth;
  out.point = ray.origin + hit.depth * ray.direction;
  out.kind = ElementKind::face;
  out.element = out.face;
  const auto& corners = triangles_.corners[t];
  int zeros = 0, nonzero = 0, zero = 0;
  for (int i = 0; i < 3; ++i) {
    if (hit.barycentric[i] == 0.0) {
      ++zeros;
      zero = i;
    } else {
      nonzero = i;
    }
  }
  if (zeros == 2) {
    out.kind = ElementKind::vertex;
    out.element = corner_vertices_[corners[nonzero]];
  } else if (zeros == 1) {
    // The side opposite the zero weight; a real polygon edge only if its corners follow each other.
    const Index p = corners[(zero + 1) % 3], q = corners[(zero + 2) % 3];
    if (corner_next_[p] == q) {
      out.kind = ElementKind::edge;
      out.element = corner_edges_[p];
    } else if (corner_next_[q] == p) {
      out.kind = ElementKind::edge;
      out.element = corner_edges_[q];
    }
  }
  return out;
}

template <typename Visit>
void TriangleBvh::traverse(const ShearedRay& sheared, double& t_max, Visit&& visit) const {
  if (nodes_.empty()) return;
  const Ray& ray = sheared.ray;
  const Vec3 inverse(1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z);
  Index stack[traversal_stack_size];
  int top = 0;
  double entry = 0.0;
  if (!ray_hits_box(nodes_[0].lower, nodes_[0].upper, ray.origin, inverse, ray.t_min, t_max, entry)) return;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = nodes_[stack[--top]];
    if (node.count > 0) {
      for (Index i = node.first; i < node.first + node.count; ++i) visit(order_[i], t_max);
      continue;
    }
    double entry_left = 0.0, entry_right = 0.0;
    const BvhNode& left = nodes_[node.first];
    const BvhNode& right = nodes_[node.first + 1];
    const bool hit_left =
        ray_hits_box(left.lower, left.upper, ray.origin, inverse, ray.t_min, t_max, entry_left);
    const bool hit_right =
        ray_hits_box(right.lower, right.upper, ray.origin, inverse, ray.t_min, t_max, entry_right);
    // Push the farther child first so the nearer one is visited first (tightens t_max sooner).
    if (hit_left && hit_right) {
      if (entry_left <= entry_right) {
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      } else {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
      }
    } else if (hit_left) {
      stack[top++] = node.first;
    } else if (hit_right) {
      stack[top++] = node.first + 1;
    }
  }
}

std::vector<RayHit> TriangleBvh::cast_all(const Ray& ray) const {
  const ShearedRay sheared(ray);
  std::vector<RayHit> hits;
  double t_max = ray.t_max;
  traverse(sheared, t_max, [&](Index t, double&) {
    TriangleHit hit;
    if (intersect(sheared, t, hit)) hits.push_back(make_hit(ray, t, hit));
  });
  return sorted_unique_hits(std::move(hits));
}

std::optional<RayHit> TriangleBvh::cast_nearest(const Ray& ray) const {
  const ShearedRay sheared(ray);
  std::optional<RayHit> best;
  double t_max = ray.t_max;
  traverse(sheared, t_max, [&](Index t, double& limit) {
    TriangleHit hit;
    if (!intersect(sheared, t, hit) || hit.depth > limit) return;
    const RayHit candidate = make_hit(ray, t, hit);
    if (!best || hit_before(candidate, *best)) {
      best = candidate;
      limit = hit.depth;
    }
  });
  return best;
}

}  // namespace nome
