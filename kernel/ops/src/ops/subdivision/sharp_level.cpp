#include "ops/subdivision/sharp_level.hpp"

#include <algorithm>

#include "ops/subdivision/crease_rules.hpp"

namespace nome {
namespace {

float sharp_weight_of(const std::vector<std::pair<Index, float>>& list, Index i) {
  const auto found =
      std::lower_bound(list.begin(), list.end(), i,
                       [](const std::pair<Index, float>& entry, Index key) { return entry.first < key; });
  return found != list.end() && found->first == i ? found->second : 0.0f;
}

void sort_unique_indices(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The patch lists from the features: every semi-sharp edge (and the extra edges already listed), the
// corners, and both ends of every listed edge (whose vertex rule, or with the report rule whose new
// edge points, change).
template <class EdgeEnds>
void finish_patch_lists(SharpLevel& s, const EdgeEnds& edge_ends) {
  for (const auto& [e, w] : s.edges) s.patch_edges.push_back(e);
  sort_unique_indices(s.patch_edges);
  for (const auto& [v, w] : s.vertices) {
    s.patch_vertices.push_back(v);
    s.needs_topology = s.needs_topology || w < infinite_sharpness;
  }
  for (Index e : s.patch_edges)
    for (Index v : edge_ends(e)) s.patch_vertices.push_back(v);
  sort_unique_indices(s.patch_vertices);
  s.needs_topology = s.needs_topology || !s.patch_edges.empty();
}

}  // namespace

float SharpLevel::edge_weight(Index e) const {
  return sharp_weight_of(edges, e);
}
float SharpLevel::vertex_weight(Index v) const {
  return sharp_weight_of(vertices, v);
}

SharpLevel base_sharp_level(const Mesh& base, const CreaseOptions& options) {
  SharpLevel s;
  s.num_faces = base.num_faces();
  s.num_edges = base.num_edges();
  if (!base.edge_sharpness_weights().empty())
    for (Index e = 0; e < base.num_edges(); ++e)
      if (!base.edge(e).is_boundary() && is_semi_sharp(base.edge_sharpness(e)))
        s.edges.emplace_back(e, base.edge_sharpness(e));
  if (!base.vertex_sharpness_weights().empty())
    for (Index v = 0; v < base.num_vertices(); ++v)
      if (base.vertex_sharpness(v) > 0.0f) s.vertices.emplace_back(v, base.vertex_sharpness(v));
  if (options.smooth_triangles) {
    for (Index e = 0; e < base.num_edges(); ++e) {
      const Edge& edge = base.edge(e);
      if (edge.is_sharp || edge.is_boundary()) continue;
      if (base.face_degree(edge.faces[0]) == 3 || base.face_degree(edge.faces[1]) == 3) {
        s.patch_edges.push_back(e);
        s.smooth_triangles = true;
      }
    }
  }
  finish_patch_lists(s, [&](Index e) { return base.edge(e).vertices; });
  return s;
}

template <class Parent>
SharpLevel child_sharp_level(const Parent& p, const SharpLevel& s, CreaseMethod method, Index child_faces,
                             Index child_edges) {
  SharpLevel c;
  c.num_faces = child_faces;
  c.num_edges = child_edges;
  const Index ep = s.num_faces, vp = s.num_faces + s.num_edges;  // where the child's points start
  std::vector<float> around, children;
  for (const auto& [e, w] : s.edges) {
    const auto ends = p.edge_ends(e);
    for (int side = 0; side < 2; ++side) {
      // The child half at this end takes its weight from the edges around the end.
      const auto fan = p.vertex_edges(ends[side]);
      around.clear();
      for (Index f : fan) around.push_back(p.is_crease(f) ? infinite_sharpness : s.edge_weight(f));
      children.resize(around.size());
      child_weights_around(method, around, children);
      const size_t i = size_t(std::find(fan.begin(), fan.end(), e) - fan.begin());
      if (children[i] > 0.0f) c.edges.emplace_back(2 * e + Index(side), children[i]);
    }
  }
  for (const auto& [v, w] : s.vertices)
    if (decayed(w) > 0.0f) c.vertices.emplace_back(vp + v, decayed(w));
  // Child edge 2e + side runs between the edge point of e and the vertex point of e's end `side`.
  finish_patch_lists(c, [&](Index child_edge) {
    const Index e = child_edge / 2;
    return std::array<Index, 2>{ep + e, vp + p.edge_ends(e)[child_edge % 2]};
  });
  return c;
}

template SharpLevel child_sharp_level(const MeshLevelView&, const SharpLevel&, CreaseMethod, Index, Index);
template SharpLevel child_sharp_level(const Refinement::Level&, const SharpLevel&, CreaseMethod, Index,
                                      Index);

}  // namespace nome
