#include "nome/query/crossings.hpp"

#include <algorithm>
#include <tuple>

#include "query/run_parts.hpp"
#include "support/union_find.hpp"

namespace nome {
namespace {

Triangle crossing_triangle(const TriangleBvh& bvh, Index t) {
  return {bvh.triangle_point(t, 0), bvh.triangle_point(t, 1), bvh.triangle_point(t, 2)};
}

bool shares_vertex(const TriangleBvh& bvh, Index t, Index u) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (bvh.triangle_vertex(t, i) == bvh.triangle_vertex(u, j)) return true;
  return false;
}

// The crossings between the triangles of two leaves (the same leaf: each pair once).
void cross_leaf_pair(const TriangleBvh& bvh, std::span<const Index> a, std::span<const Index> b,
                     std::vector<Crossing>& out) {
  const auto& faces = bvh.triangles().faces;
  const bool same = a.data() == b.data();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Index t = a[i];
    const Triangle first = crossing_triangle(bvh, t);
    for (std::size_t j = same ? i + 1 : 0; j < b.size(); ++j) {
      const Index u = b[j];
      if (faces[u] == faces[t] || shares_vertex(bvh, t, u)) continue;
      Crossing crossing;
      if (!triangles_cross(first, crossing_triangle(bvh, u), crossing.segment)) continue;
      crossing.face = std::min(faces[t], faces[u]);
      crossing.other_face = std::max(faces[t], faces[u]);
      out.push_back(crossing);
    }
  }
}

// Joins pairs into curves: a pair joins its two faces, and crossing faces that share a vertex are one
// curve's neighbours.
void join_crossing_curves(const Mesh& surface, Crossings& crossings) {
  std::vector<char> is_crossing(surface.num_faces(), 0);
  for (const Index f : crossings.faces) is_crossing[f] = 1;
  UnionFind sets(surface.num_faces());
  for (const Crossing& c : crossings.pairs) sets.unite(c.face, c.other_face);
  for (const Index f : crossings.faces)
    for (const Index v : surface.face_vertices(f))
      for (const Index c : surface.vertex_corners(v))
        if (is_crossing[surface.corner_face(c)]) sets.unite(f, surface.corner_face(c));
  std::vector<Index> curve_of_root(surface.num_faces(), no_index);
  for (const Crossing& c : crossings.pairs) {
    Index& curve = curve_of_root[sets.find(c.face)];
    if (curve == no_index) curve = crossings.curves++;
    crossings.curve_of_pair.push_back(curve);
  }
}

}  // namespace

Crossings find_crossings(const Mesh& surface, const TriangleBvh& bvh, int threads) {
  const int count = std::max(1, std::min(threads, 2));
  std::vector<std::vector<Crossing>> found(count);
  run_parts(count, [&](int part) {
    bvh.visit_overlapping_leaves(part, count, [&](std::span<const Index> a, std::span<const Index> b) {
      cross_leaf_pair(bvh, a, b, found[part]);
    });
  });
  Crossings crossings;
  for (auto& part : found) crossings.pairs.insert(crossings.pairs.end(), part.begin(), part.end());
  std::sort(crossings.pairs.begin(), crossings.pairs.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.face, x.other_face, x.segment.from.x, x.segment.from.y, x.segment.from.z) <
           std::tie(y.face, y.other_face, y.segment.from.x, y.segment.from.y, y.segment.from.z);
  });
  for (const Crossing& c : crossings.pairs) {
    crossings.faces.push_back(c.face);
    crossings.faces.push_back(c.other_face);
  }
  std::sort(crossings.faces.begin(), crossings.faces.end());
  crossings.faces.erase(std::unique(crossings.faces.begin(), crossings.faces.end()), crossings.faces.end());
  join_crossing_curves(surface, crossings);
  return crossings;
}

}  // namespace nome
