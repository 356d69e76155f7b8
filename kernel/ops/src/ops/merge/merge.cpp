#include "nome/ops/merge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <optional>

#include "mesh/sharpness.hpp"
#include "nome/mesh/concatenate.hpp"

namespace nome {
namespace {

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Boundary vertices bucketed by grid cell and sorted by cell, their positions copied in that order so
// that the distance tests read memory in sequence. Cells are 8 tolerances wide: most points lie
// farther than the tolerance from every cell face and are compared within their own cell only; a point
// near a face also searches the cell across it (at most 8 cells), found through an open-addressing
// table keyed by a hash of the cell coordinates. Two cells sharing a hash only add candidates that the
// distance test rejects.
class PointGrid {
 public:
  PointGrid(std::span<const Vec3> positions, const std::vector<Index>& points, double tolerance) {
    Vec3 lo(0.0), hi(0.0);
    if (!points.empty()) lo = hi = positions[points.front()];
    for (Index v : points) {
      lo = glm::min(lo, positions[v]);
      hi = glm::max(hi, positions[v]);
    }
    origin_ = lo;
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    // A zero tolerance matches equal points only; the cell side just has to keep the coordinates small.
    cell_ = std::max(tolerance > 0 ? 8 * tolerance : 1.0, extent * 0x1p-40);
    margin_ = 1.01 * tolerance / cell_;
    tolerance2_ = tolerance * tolerance;

    std::vector<std::pair<std::uint64_t, Index>> keyed(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      const Vec3 g = glm::floor((positions[points[i]] - origin_) / cell_);
      keyed[i] = {key(std::int64_t(g.x), std::int64_t(g.y), std::int64_t(g.z)), Index(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    order_.resize(keyed.size());
    positions_.resize(keyed.size());
    for (size_t i = 0; i < keyed.size(); ++i) {
      order_[i] = keyed[i].second;
      positions_[i] = positions[points[keyed[i].second]];
    }

    size_t capacity = 16;
    while (capacity < 2 * keyed.size()) capacity *= 2;
    mask_ = capacity - 1;
    slots_.assign(capacity, Slot{0, no_index});
    bucket_starts_.assign(1, 0);
    for (size_t i = 0; i < keyed.size();) {
      size_t end = i + 1;
      while (end < keyed.size() && keyed[end].first == keyed[i].first) ++end;
      size_t s = keyed[i].first & mask_;
      while (slots_[s].bucket != no_index) s = (s + 1) & mask_;
      slots_[s] = {keyed[i].first, Index(bucket_keys_.size())};
      bucket_keys_.push_back(keyed[i].first);
      bucket_starts_.push_back(Index(end));
      i = end;
    }
  }

  // Indices into `points`, in cell order.
  const std::vector<Index>& order() const { return order_; }

  // Calls visit(i, j, squared distance) once for every pair of points at most the tolerance apart, as
  // indices into order() with order()[i] <= order()[j] (every point is paired with itself too).
  template <typename Visit>
  void for_each_close_pair(Visit&& visit) const {
    auto compare = [&](Index i, Index j) {
      const Vec3 d = positions_[i] - positions_[j];
      const double d2 = glm::dot(d, d);
      if (order_[i] <= order_[j] && d2 <= tolerance2_) visit(i, j, d2);
    };
    for (size_t b = 0; b < bucket_keys_.size(); ++b) {
      const Index begin = bucket_starts_[b], end = bucket_starts_[b + 1];
      for (Index i = begin; i < end; ++i) {
        for (Index j = begin; j < end; ++j) compare(i, j);
        const Vec3 g = (positions_[i] - origin_) / cell_;
        const Vec3 f = glm::floor(g);
        std::int64_t lo[3], hi[3];
        for (int d = 0; d < 3; ++d) {
          lo[d] = std::int64_t(f[d]) - (g[d] - f[d] < margin_ ? 1 : 0);
          hi[d] = std::int64_t(f[d]) + (f[d] + 1 - g[d] < margin_ ? 1 : 0);
        }
        if (lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) continue;
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
          for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
            for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
              const std::uint64_t h = key(x, y, z);
              if (h == bucket_keys_[b]) continue;
              for (size_t s = h & mask_; slots_[s].bucket != no_index; s = (s + 1) & mask_) {
                if (slots_[s].key != h) continue;
                const Index other = slots_[s].bucket;
                for (Index j = bucket_starts_[other]; j < bucket_starts_[other + 1]; ++j) compare(i, j);
                break;
              }
            }
      }
    }
  }

 private:
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return mix(std::uint64_t(x) + mix(std::uint64_t(y) + mix(std::uint64_t(z))));
  }

  Vec3 origin_{0.0};
  double cell_ = 1.0;
  double margin_ = 0.0;
  double tolerance2_ = 0.0;
  std::vector<Index> order_;                // indices into the points, in cell order
  std::vector<Vec3> positions_;             // their positions
  std::vector<std::uint64_t> bucket_keys_;  // one bucket per occupied cell
  std::vector<Index> bucket_starts_;        // CSR into order_ and positions_
  size_t mask_ = 0;
  struct Slot {
    std::uint64_t key;
    Index bucket;  // no_index: empty
  };
  std::vector<Slot> slots_;
};

// Union-find over vertices that also keeps each class's members on a cycle, so a class can be walked.
class VertexClasses {
 public:
  explicit VertexClasses(Index n) : parent_(n), size_(n, 1), next_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
    std::iota(next_.begin(), next_.end(), 0);
  }
  Index find(Index v) {
    while (parent_[v] != v) {
      parent_[v] = parent_[parent_[v]];
      v = parent_[v];
    }
    return v;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    std::swap(next_[a], next_[b]);  // splices the two member cycles into one
  }
  template <typename Visit>
  void for_each_member(Index root, Visit&& visit) const {
    Index v = root;
    do {
      visit(v);
      v = next_[v];
    } while (v != root);
  }

 private:
  std::vector<Index> parent_;
  std::vector<Index> size_;
  std::vector<Index> next_;
};

// Two boundary edges whose ends match: ends_a[i] lies within the tolerance of ends_b[i].
struct Candidate {
  double distance;  // the larger of the two end-point distances: closest pairs are glued first
  std::array<Index, 2> edges;
  std::array<Index, 2> ends_a;
  std::array<Index, 2> ends_b;
};

// A boundary vertex's two border edges and their far ends.
struct BorderStep {
  std::array<Index, 2> edges;
  std::array<Index, 2> far_ends;
  std::array<Vec3, 2> far_positions;
};

std::vector<Candidate> find_candidates(const Mesh& mesh, double tolerance) {
  const auto& pos = mesh.positions();
  std::vector<Index> boundary;
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.is_boundary_vertex(v)) boundary.push_back(v);
  const PointGrid grid(pos, boundary, tolerance);
  const double tol2 = tolerance * tolerance;
  auto dist2 = [](const Vec3& a, const Vec3& b) { return glm::dot(a - b, a - b); };

  // Computed in vertex order (neighbouring vertices share memory), then gathered once into cell
  // order, so that testing a close pair reads no scattered memory.
  std::vector<BorderStep> by_vertex(boundary.size());
  for (size_t k = 0; k < boundary.size(); ++k) {
    const Index v = boundary[k];
    const auto fan = mesh.vertex_edges(v);
    BorderStep& step = by_vertex[k];
    step.edges = {fan.front(), fan.back()};
    for (int k = 0; k < 2; ++k) {
      step.far_ends[k] = mesh.edge(step.edges[k]).other_vertex(v);
      step.far_positions[k] = pos[step.far_ends[k]];
    }
  }
  const std::vector<Index>& order = grid.order();
  std::vector<BorderStep> steps(order.size());
  std::vector<Index> ids(order.size());
  for (size_t i = 0; i < order.size(); ++i) {
    steps[i] = by_vertex[order[i]];
    ids[i] = boundary[order[i]];
  }
  by_vertex = {};

  // Each edge pair is reached through both of its matched vertex pairs; it is kept from the one that
  // reaches the lower-numbered edge at that edge's lower-numbered end. A vertex is paired with itself
  // too, which finds two border edges folding together at their common end.
  std::vector<Candidate> out;
  grid.for_each_close_pair([&](Index i, Index j, double near2) {
    const Index u = ids[i], w = ids[j];
    const BorderStep &su = steps[i], &sw = steps[j];
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        const Index eu = su.edges[a], ew = sw.edges[b];
        if (eu == ew || (u == w && eu > ew)) continue;
        const double far2 = dist2(su.far_positions[a], sw.far_positions[b]);
        if (far2 > tol2) continue;
        const Index u2 = su.far_ends[a], w2 = sw.far_ends[b];
        const bool keep = eu < ew ? u < u2 : w < w2;
        if (keep) out.push_back({std::sqrt(std::max(near2, far2)), {eu, ew}, {u, u2}, {w, w2}});
      }
    }
  });
  std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.edges < b.edges;
  });
  return out;
}

std::string point_text(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
  return buf;
}

// Decides whether a candidate can be glued given the classes formed so far, without changing them.
class GlueCheck {
 public:
  GlueCheck(const Mesh& mesh, VertexClasses& classes) : mesh_(mesh), classes_(classes) {}

  struct Problem {
    MergeSkipReason reason;
    Index at;     // the merged vertex (a class root) where it shows
    Index other;  // for a third face: the far end of that edge
  };

  // The edge pair is already one edge when both end classes coincide.
  bool is_glued(const Candidate& c) {
    const Index a0 = classes_.find(c.ends_a[0]), a1 = classes_.find(c.ends_a[1]);
    const Index b0 = classes_.find(c.ends_b[0]), b1 = classes_.find(c.ends_b[1]);
    return (a0 == b0 && a1 == b1) || (a0 == b1 && a1 == b0);
  }

  std::optional<Problem> problem(const Candidate& c) {
    x_ = {classes_.find(c.ends_a[0]), classes_.find(c.ends_b[0])};
    y_ = {classes_.find(c.ends_a[1]), classes_.find(c.ends_b[1])};
    if (x_[0] == y_[0] || x_[0] == y_[1] || x_[1] == y_[0] || x_[1] == y_[1])
      return Problem{MergeSkipReason::edge_would_collapse, x_[0], y_[0]};
    if (auto p = problem_at(x_)) return p;
    return problem_at(y_);
  }

 private:
  // The class a vertex would belong to after the glue.
  Index merged(Index v) {
    const Index r = classes_.find(v);
    return r == x_[1] ? x_[0] : r == y_[1] ? y_[0] : r;
  }

  // Every face may visit the merged vertex once, every edge at it may have two faces.
  std::optional<Problem> problem_at(const std::array<Index, 2>& roots) {
    faces_.clear();
    neighbours_.clear();
    bool repeated = false;
    for (int i = 0; i < (roots[0] == roots[1] ? 1 : 2); ++i) {
      classes_.for_each_member(roots[i], [&](Index v) {
        for (Index corner : mesh_.vertex_corners(v)) {
          faces_.push_back(mesh_.corner_face(corner));
          const Index next = merged(mesh_.corner_vertex(mesh_.next_corner(corner)));
          const Index prev = merged(mesh_.corner_vertex(mesh_.prev_corner(corner)));
          repeated = repeated || next == roots[0] || prev == roots[0];
          neighbours_.push_back(next);
          neighbours_.push_back(prev);
        }
      });
    }
    std::sort(faces_.begin(), faces_.end());
    if (repeated || std::adjacent_find(faces_.begin(), faces_.end()) != faces_.end())
      return Problem{MergeSkipReason::vertex_repeated_in_face, roots[0], no_index};
    std::sort(neighbours_.begin(), neighbours_.end());
    for (size_t i = 0; i + 2 < neighbours_.size(); ++i)
      if (neighbours_[i] == neighbours_[i + 2])
        return Problem{MergeSkipReason::third_face_on_edge, roots[0], neighbours_[i]};
    return std::nullopt;
  }

  const Mesh& mesh_;
  VertexClasses& classes_;
  std::array<Index, 2> x_{}, y_{};
  std::vector<Index> faces_;
  std::vector<Index> neighbours_;
};

SkippedMerge describe(const Mesh& mesh, const Candidate& c, const GlueCheck::Problem& p) {
  auto edge_text = [&](const std::array<Index, 2>& ends) {
    return "(" + mesh.vertex_label(ends[0]) + " " + point_text(mesh.position(ends[0])) + ", " +
           mesh.vertex_label(ends[1]) + " " + point_text(mesh.position(ends[1])) + ")";
  };
  std::string why;
  switch (p.reason) {
    case MergeSkipReason::edge_would_collapse:
      why = "both ends of an edge would become one vertex";
      break;
    case MergeSkipReason::vertex_repeated_in_face:
      why = "a face would visit the vertex at " + mesh.vertex_label(p.at) + " twice";
      break;
    case MergeSkipReason::third_face_on_edge:
      why = "the edge (" + mesh.vertex_label(p.at) + ", " + mesh.vertex_label(p.other) +
            ") would have a third face";
      break;
  }
  return {p.reason,
          c.edges,
          {mesh.position(c.ends_a[0]), mesh.position(c.ends_a[1])},
          "boundary edges " + edge_text(c.ends_a) + " and " + edge_text(c.ends_b) + " not merged: " + why};
}

double bounding_box_diagonal(std::span<const Vec3> positions) {
  if (positions.empty()) return 0.0;
  Vec3 lo = positions.front(), hi = positions.front();
  for (const Vec3& p : positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

}  // namespace

MergePlan plan_merge(const Mesh& mesh, const MergeOptions& options) {
  MergePlan plan;
  plan.tolerance = options.tolerance > 0
                       ? options.tolerance
                       : options.relative_tolerance * bounding_box_diagonal(mesh.positions());

  // phase: glue matching boundary edge pairs, closest first, each only if the surface stays 2-manifold.
  VertexClasses classes(mesh.num_vertices());
  GlueCheck check(mesh, classes);
  for (const Candidate& c : find_candidates(mesh, plan.tolerance)) {
    if (check.is_glued(c)) continue;
    if (const auto problem = check.problem(c)) {
      plan.skipped.push_back(describe(mesh, c, *problem));
      continue;
    }
    classes.unite(c.ends_a[0], c.ends_b[0]);
    classes.unite(c.ends_a[1], c.ends_b[1]);
  }

  // phase: one vertex per class, numbered by its lowest member.
  plan.vertex_map.assign(mesh.num_vertices(), no_index);
  std::vector<Index> class_vertex(mesh.num_vertices(), no_index);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    Index& id = class_vertex[classes.find(v)];
    if (id == no_index) id = plan.num_vertices++;
    plan.vertex_map[v] = id;
  }
  return plan;
}

void merged_positions(const Mesh& mesh, const MergePlan& plan, Buffer<Vec3>& positions) {
  positions.assign(plan.num_vertices, Vec3(0.0));
  std::vector<Index> class_size(plan.num_vertices, 0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    positions[plan.vertex_map[v]] += mesh.position(v);
    ++class_size[plan.vertex_map[v]];
  }
  for (Index i = 0; i < plan.num_vertices; ++i) positions[i] /= double(class_size[i]);
}

MergeResult merge_by_plan(const Mesh& mesh, MergePlan plan) {
  PolygonSoup soup;
  merged_positions(mesh, plan, soup.positions);
  if (!mesh.vertex_names().empty()) {
    std::vector<std::string>& names = soup.vertex_names.writable();
    names.resize(plan.num_vertices);
    for (Index v = mesh.num_vertices(); v-- > 0;) names[plan.vertex_map[v]] = mesh.vertex_names()[v];
  }
  soup.face_offsets = mesh.face_offsets();
  soup.face_vertices.reserve(mesh.num_corners());
  for (Index v : mesh.corner_vertices()) soup.face_vertices.push_back(plan.vertex_map[v]);
  soup.face_names = mesh.face_names();
  soup.face_attributes = carried(mesh.face_attributes(), ElementOrigins::identity());
  add_features_to_soup(mesh, soup);
  for (auto& [a, b] : soup.sharp_edges) a = plan.vertex_map[a], b = plan.vertex_map[b];
  for (auto& [v, w] : soup.sharp_vertices) v = plan.vertex_map[v];

  MergeResult result;
  result.mesh = build_mesh(std::move(soup));
  auto boundary_edges = [](const Mesh& m) {
    return Index(
        std::count_if(m.edges().begin(), m.edges().end(), [](const Edge& e) { return e.is_boundary(); }));
  };
  result.glued_edges = (boundary_edges(mesh) - boundary_edges(result.mesh)) / 2;
  result.vertex_map = std::move(plan.vertex_map);
  result.tolerance = plan.tolerance;
  result.skipped = std::move(plan.skipped);
  return result;
}

MergeResult merge_boundaries(const Mesh& mesh, const MergeOptions& options) {
  return merge_by_plan(mesh, plan_merge(mesh, options));
}

MergeResult merge_meshes(std::span<const Mesh> parts, const MergeOptions& options) {
  return merge_boundaries(build_mesh(concatenate(parts)), options);
}

}  // namespace nome
