#include <array>
#include <vector>

#include "ops/subdivision/crease_rules.hpp"
#include "ops/subdivision/sharp_level.hpp"
#include "support/parallel_for.hpp"

namespace nome {
namespace {

// OpenSubdiv's Catmark edge weights for the smooth triangles option (Hbr's constant).
constexpr double smooth_triangle_weight = 0.470;

template <class Parent>
Vec3 sharp_edge_point(const Parent& p, const SharpLevel& s, const SharpRules& rules, Index e,
                      std::span<const Vec3> in, std::span<const Vec3> out) {
  const auto ends = p.edge_ends(e);
  const Vec3 sum = in[ends[0]] + in[ends[1]];
  const float w = s.edge_weight(e);
  const Index fa = p.corner_face(p.edge_corner(e, 0)), fb = p.corner_face(p.edge_corner(e, 1));
  // The smooth mask: vertices and face points a quarter each, unless beside a smoothed triangle.
  double vertex_w = 0.25, face_w = 0.25;
  if (s.smooth_triangles) {
    const bool tri_a = p.face_end(fa) - p.face_begin(fa) == 3, tri_b = p.face_end(fb) - p.face_begin(fb) == 3;
    if (tri_a || tri_b) {
      face_w = 0.5 * ((tri_a ? smooth_triangle_weight : 0.25) + (tri_b ? smooth_triangle_weight : 0.25));
      vertex_w = 0.5 * (1.0 - 2.0 * face_w);
    }
  }
  if (w > 0.0f) {
    // The child is a crease when both halves stay sharp; otherwise the parent's crease is blended in by
    // the weight (not clamped: a Chaikin weight above 1 whose half decays extrapolates, as in OpenSubdiv).
    bool is_crease = decayed(w) > 0.0f;
    if (rules.method == CreaseMethod::chaikin) {
      is_crease = true;
      std::vector<float> around, children;
      for (int side = 0; side < 2; ++side) {
        const auto fan = p.vertex_edges(ends[side]);
        around.clear();
        for (Index f : fan) around.push_back(p.is_crease(f) ? infinite_sharpness : s.edge_weight(f));
        children.resize(around.size());
        child_weights_around(rules.method, around, children);
        for (size_t i = 0; i < fan.size(); ++i)
          if (fan[i] == e) is_crease = is_crease && children[i] > 0.0f;
      }
    }
    if (is_crease) return sum * 0.5;
    const double parent = w, child = 1.0 - parent;
    vertex_w = parent * 0.5 + child * vertex_w;
    face_w *= child;
  }
  return vertex_w * sum + face_w * (out[fa] + out[fb]);
}

// A vertex point by one rule, the crease between the sharp edges first and last in the fan.
template <class Parent>
Vec3 vertex_point_by_rule(const Parent& p, VertexRule rule, const SharpRules& rules, Index v,
                          std::span<const float> sharp, std::span<const Vec3> in, std::span<const Vec3> out) {
  const Vec3& here = in[v];
  const auto edges = p.vertex_edges(v);
  const auto other = [&](Index e) {
    const auto ends = p.edge_ends(e);
    return in[ends[0] == v ? ends[1] : ends[0]];
  };
  if (rule == VertexRule::corner) return here;
  if (rule == VertexRule::crease) {
    size_t first = 0, last = sharp.size() - 1;
    while (sharp[first] <= 0.0f) ++first;
    while (sharp[last] <= 0.0f) --last;
    return 0.75 * here + 0.125 * (other(edges[first]) + other(edges[last]));
  }
  Vec3 face_sum(0.0), edge_sum(0.0);
  for (Index c : p.vertex_corners(v)) face_sum += out[p.corner_face(c)];
  for (Index e : edges)
    edge_sum += rules.vertex.rule == SubdivisionRule::classic ? other(e) : out[p.num_faces() + e];
  return smooth_vertex_point(here, edge_sum, face_sum, double(edges.size()));
}

template <class Parent>
Vec3 sharp_vertex_point(const Parent& p, const SharpLevel& s, const SharpRules& rules, Index v,
                        std::span<const Vec3> in, std::span<const Vec3> out) {
  float vertex_w = s.vertex_weight(v);
  if (vertex_w >= infinite_sharpness) return in[v];  // no topology read: it may not be there
  const auto edges = p.vertex_edges(v);
  if (rules.vertex.is_fixed(edges.size(), p.vertex_corners(v).size(), 0)) return in[v];
  std::vector<float> parent(edges.size()), child(edges.size());
  int sharp = 0;
  for (size_t i = 0; i < edges.size(); ++i) {
    parent[i] = p.is_crease(edges[i]) ? infinite_sharpness : s.edge_weight(edges[i]);
    sharp += parent[i] > 0.0f ? 1 : 0;
  }
  const VertexRule parent_rule = vertex_rule(vertex_w, sharp);
  const Vec3 parent_point = vertex_point_by_rule(p, parent_rule, rules, v, parent, in, out);
  if (parent_rule == VertexRule::smooth || parent_rule == VertexRule::dart) return parent_point;
  child_weights_around(rules.method, parent, child);
  const float child_vertex_w = decayed(vertex_w);
  int child_sharp = 0;
  for (float w : child) child_sharp += w > 0.0f ? 1 : 0;
  const VertexRule child_rule = child_vertex_w > 0.0f ? VertexRule::corner : vertex_rule(0.0f, child_sharp);
  if (child_rule == parent_rule) return parent_point;
  const double blend = fractional_weight(rules.method, vertex_w, child_vertex_w, parent, child);
  return blend * parent_point + (1.0 - blend) * vertex_point_by_rule(p, child_rule, rules, v, child, in, out);
}

}  // namespace

template <class Parent>
void refine_sharp_positions(const Parent& p, const SharpLevel& s, const SharpRules& rules,
                            std::span<const Vec3> in, std::span<Vec3> out, int threads) {
  const Index ep = s.num_faces, vp = s.num_faces + s.num_edges;
  parallel_for(Index(s.patch_edges.size()), threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
      out[ep + s.patch_edges[i]] = sharp_edge_point(p, s, rules, s.patch_edges[i], in, out);
  });
  parallel_for(Index(s.patch_vertices.size()), threads, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i) {
      const Index v = s.patch_vertices[i];
      out[vp + v] = sharp_vertex_point(p, s, rules, v, in, out);
    }
  });
}

template void refine_sharp_positions(const MeshLevelView&, const SharpLevel&, const SharpRules&,
                                     std::span<const Vec3>, std::span<Vec3>, int);
template void refine_sharp_positions(const Refinement::Level&, const SharpLevel&, const SharpRules&,
                                     std::span<const Vec3>, std::span<Vec3>, int);

}  // namespace nome
