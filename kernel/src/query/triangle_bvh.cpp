#include "nome/query/triangle_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <thread>
#include <utility>

namespace nome {
namespace {

// Build-time boxes in float (half the memory traffic of double), rounded outward so that they still
// contain the double-precision triangles; node boxes are stored in double.
struct Box {
  glm::vec3 lower{std::numeric_limits<float>::infinity()};
  glm::vec3 upper{-std::numeric_limits<float>::infinity()};

  void grow(const glm::vec3& p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void grow(const Box& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
  float half_area() const {
    const glm::vec3 d = upper - lower;
    return d.x < 0.0f ? 0.0f : d.x * d.y + d.y * d.z + d.z * d.x;
  }
};

float round_down(double x) {
  const float f = static_cast<float>(x);
  return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double x) {
  const float f = static_cast<float>(x);
  return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// One triangle during the build: partitions move these records, so each pass reads memory in order.
struct BuildItem {
  Box box;
  Index triangle;
  glm::vec3 centroid() const { return 0.5f * (box.lower + box.upper); }
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

// Median splits below this depth keep the whole tree under max_sah_depth + 32 levels (2^32 triangles).
constexpr Index max_sah_depth = 64;
constexpr int traversal_stack_size = 128;

// One node to build: its triangles items[begin, end), bounds, and centroid range (from the parent's
// bins, so that every level costs one binning pass and one partition over its triangles).
struct BuildTask {
  Index node, begin, end, depth;
  Box bounds, centroid_bounds;
};

struct BinScratch {
  explicit BinScratch(Index bins)
      : bins(std::max<Index>(2, bins)),
        boxes(this->bins),
        left(this->bins),
        right(this->bins),
        counts(this->bins) {}
  Index bins;
  std::vector<Box> boxes, left, right;
  std::vector<Index> counts;
};

// Splits a task into two children (binned SAH, Wald 2007, along the axis of largest centroid extent;
// median split when SAH finds nothing or the tree is already deep); false when it is a leaf.
bool split_task(std::vector<BuildItem>& items, const BuildTask& task, const BvhOptions& options,
                BinScratch& scratch, BuildTask children[2]) {
  const Index count = task.end - task.begin;
  if (count <= options.max_leaf_size) return false;
  const glm::vec3 extent = task.centroid_bounds.upper - task.centroid_bounds.lower;
  int axis = 0;
  if (extent.y > extent[axis]) axis = 1;
  if (extent.z > extent[axis]) axis = 2;
  Index mid = task.begin + count / 2;
  Box child_bounds[2], child_centroids[2];
  bool is_split = false;
  const Index bins = scratch.bins;
  if (extent[axis] > 0.0f && task.depth < max_sah_depth) {
    const float scale = float(bins) / extent[axis];
    const float origin = task.centroid_bounds.lower[axis];
    auto bin_of = [&](const BuildItem& it) {
      const float x = (it.centroid()[axis] - origin) * scale;
      return x >= 0.0f ? std::min<Index>(bins - 1, Index(std::min(x, float(bins)))) : Index{0};
    };
    std::fill(scratch.boxes.begin(), scratch.boxes.end(), Box{});
    std::fill(scratch.counts.begin(), scratch.counts.end(), 0);
    for (Index i = task.begin; i < task.end; ++i) {
      const Index b = bin_of(items[i]);
      scratch.boxes[b].grow(items[i].box);
      ++scratch.counts[b];
    }
    Box right, left;
    for (Index b = bins - 1; b > 0; --b) {
      right.grow(scratch.boxes[b]);
      scratch.right[b] = right;
    }
    Index left_count = 0, best_split = 0;
    float best_cost = std::numeric_limits<float>::infinity();
    for (Index b = 0; b + 1 < bins; ++b) {
      left.grow(scratch.boxes[b]);
      scratch.left[b] = left;
      left_count += scratch.counts[b];
      const float cost =
          left.half_area() * float(left_count) + scratch.right[b + 1].half_area() * float(count - left_count);
      if (left_count > 0 && left_count < count && cost < best_cost) {
        best_cost = cost;
        best_split = b + 1;
      }
    }
    if (best_split > 0) {
      const auto split = std::partition(items.begin() + task.begin, items.begin() + task.end,
                                        [&](const BuildItem& it) { return bin_of(it) < best_split; });
      mid = Index(split - items.begin());
      child_bounds[0] = scratch.left[best_split - 1];
      child_bounds[1] = scratch.right[best_split];
      // The children's centroid ranges: the parent's, cut at the split plane. A centroid rounded
      // across the plane only lands in an end bin of the child: binning stays a heuristic, while node
      // boxes are exact.
      const float plane = origin + float(best_split) / scale;
      child_centroids[0] = child_centroids[1] = task.centroid_bounds;
      child_centroids[0].upper[axis] = std::min(plane, task.centroid_bounds.upper[axis]);
      child_centroids[1].lower[axis] = std::max(plane, task.centroid_bounds.lower[axis]);
      is_split = true;
    }
  }
  if (!is_split) {
    std::nth_element(
        items.begin() + task.begin, items.begin() + mid, items.begin() + task.end,
        [&](const BuildItem& a, const BuildItem& b) { return a.centroid()[axis] < b.centroid()[axis]; });
    for (Index i = task.begin; i < task.end; ++i) {
      const int side = i < mid ? 0 : 1;
      child_bounds[side].grow(items[i].box);
      child_centroids[side].grow(items[i].centroid());
    }
  }
  children[0] = {no_index, task.begin, mid, task.depth + 1, child_bounds[0], child_centroids[0]};
  children[1] = {no_index, mid, task.end, task.depth + 1, child_bounds[1], child_centroids[1]};
  return true;
}

// Builds the subtree of `root` into `nodes`, root first; a node's children are adjacent.
void build_subtree(std::vector<BuildItem>& items, BuildTask root, const BvhOptions& options,
                   std::vector<BvhNode>& nodes) {
  BinScratch scratch(options.sah_bins);
  nodes.reserve(2 * ((root.end - root.begin) / std::max<Index>(1, options.max_leaf_size)) + 1);
  nodes.push_back(BvhNode{});
  root.node = 0;
  std::vector<BuildTask> stack{root};
  BuildTask children[2];
  while (!stack.empty()) {
    const BuildTask task = stack.back();
    stack.pop_back();
    BvhNode& node = nodes[task.node];
    node.lower = Vec3(task.bounds.lower);
    node.upper = Vec3(task.bounds.upper);
    if (!split_task(items, task, options, scratch, children)) {
      node.first = task.begin;
      node.count = task.end - task.begin;
      continue;
    }
    const Index left_child = static_cast<Index>(nodes.size());
    node.first = left_child;
    node.count = 0;
    nodes.push_back(BvhNode{});
    nodes.push_back(BvhNode{});
    children[0].node = left_child;
    children[1].node = left_child + 1;
    stack.push_back(children[1]);
    stack.push_back(children[0]);
  }
}

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
  std::vector<BuildItem> items(n);
  Box root_bounds, root_centroids;
  for (Index t = 0; t < n; ++t) {
    Vec3 lower(std::numeric_limits<double>::infinity()), upper(-std::numeric_limits<double>::infinity());
    for (Index c : triangles_.corners[t]) {
      lower = glm::min(lower, positions_[corner_vertices_[c]]);
      upper = glm::max(upper, positions_[corner_vertices_[c]]);
    }
    items[t].box.lower = {round_down(lower.x), round_down(lower.y), round_down(lower.z)};
    items[t].box.upper = {round_up(upper.x), round_up(upper.y), round_up(upper.z)};
    items[t].triangle = t;
    root_bounds.grow(items[t].box);
    root_centroids.grow(items[t].centroid());
  }
  if (n == 0) return;
  const BuildTask root{0, 0, n, 0, root_bounds, root_centroids};
  BinScratch scratch(options.sah_bins);
  BuildTask children[2];
  // The two halves of a large mesh are built on two threads (the machine we target has two cores).
  if (n >= options.parallel_build_threshold && split_task(items, root, options, scratch, children)) {
    std::vector<BvhNode> left, right;
    std::thread worker([&] { build_subtree(items, children[1], options, right); });
    build_subtree(items, children[0], options, left);
    worker.join();
    // Root, the two subtree roots, then the rest of each subtree; inner nodes' child ids shift.
    nodes_.reserve(1 + left.size() + right.size());
    BvhNode top;
    top.lower = Vec3(root.bounds.lower);
    top.upper = Vec3(root.bounds.upper);
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
    build_subtree(items, root, options, nodes_);
  }
  order_.resize(n);
  for (Index i = 0; i < n; ++i) order_[i] = items[i].triangle;
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
