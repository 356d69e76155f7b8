#include "nome/query/fold_overs.hpp"

#include <array>

#include <glm/geometric.hpp>

#include "support/parallel_for.hpp"

namespace nome {
namespace {

// Corner c moved by shift * s(c) * n_v: its place on one of the offset's two copies of its face.
Vec3 moved_corner(const Mesh& mesh, const Normals& normals, Index c, double shift) {
  const Index v = mesh.corner_vertex(c);
  return mesh.position(v) + (shift * mesh.corner_sign(c)) * normals.vertices[v];
}

// Newell's normal of face f's offset copy.
Vec3 offset_copy_normal(const Mesh& mesh, const Normals& normals, Index f, double shift) {
  Vec3 normal(0.0);
  const Index first = mesh.face_first_corner(f), degree = mesh.face_degree(f);
  Vec3 current = moved_corner(mesh, normals, first, shift);
  for (Index i = 0; i < degree; ++i) {
    const Vec3 next = moved_corner(mesh, normals, first + (i + 1) % degree, shift);
    normal += glm::cross(current, next);
    current = next;
  }
  return normal;
}

// The mean of face f's corners on its offset copy.
Vec3 copy_centroid(const Mesh& mesh, const Normals& normals, Index f, double shift) {
  Vec3 sum(0.0);
  const Index first = mesh.face_first_corner(f), degree = mesh.face_degree(f);
  for (Index c = first; c < first + degree; ++c) sum += moved_corner(mesh, normals, c, shift);
  return sum / double(degree);
}

// The corner of face f at vertex v.
Index corner_at(const Mesh& mesh, Index f, Index v) {
  const Index first = mesh.face_first_corner(f);
  for (Index c = first; c < first + mesh.face_degree(f); ++c)
    if (mesh.corner_vertex(c) == v) return c;
  return no_index;
}

// The angle between two faces around their shared edge from u to w, as its sine and cosine (unscaled):
// each face is represented by the direction from the edge to its centroid, across the edge.
std::array<double, 2> opening(const Vec3& u, const Vec3& w, const Vec3& a, const Vec3& b) {
  const Vec3 along = w - u;
  const double length2 = glm::dot(along, along);
  if (length2 == 0.0) return {0.0, 0.0};
  const Vec3 to_a = (a - u) - along * (glm::dot(a - u, along) / length2);
  const Vec3 to_b = (b - u) - along * (glm::dot(b - u, along) / length2);
  return {glm::dot(glm::cross(to_a, to_b), along), glm::dot(to_a, to_b)};
}

// Whether the copies of edge e's two faces on one side of the slab have passed through each other: the
// angle between them at the edge closed through zero (its sine changed sign while the faces point the
// same way from the edge), which is where each copy intersects its neighbour. Face b's copy on a's side is
// the one through the same offset vertices: its shift takes the corner signs' ratio at the edge.
bool edge_folds(const Mesh& mesh, const Normals& normals, Index e, double distance) {
  const Edge& edge = mesh.edge(e);
  if (edge.faces[1] == no_index) return false;
  const auto [fa, fb] = edge.faces;
  const auto [u, w] = edge.vertices;
  const Index ua = corner_at(mesh, fa, u), ub = corner_at(mesh, fb, u), wa = corner_at(mesh, fa, w);
  const std::array<double, 2> before =
      opening(mesh.position(u), mesh.position(w), copy_centroid(mesh, normals, fa, 0.0),
              copy_centroid(mesh, normals, fb, 0.0));
  if (before[0] == 0.0) return false;
  for (const double shift : {distance, -distance}) {
    const double shift_b = shift * mesh.corner_sign(ua) * mesh.corner_sign(ub);
    const std::array<double, 2> after =
        opening(moved_corner(mesh, normals, ua, shift), moved_corner(mesh, normals, wa, shift),
                copy_centroid(mesh, normals, fa, shift), copy_centroid(mesh, normals, fb, shift_b));
    if (after[1] > 0.0 && (after[0] > 0.0) != (before[0] > 0.0)) return true;
  }
  return false;
}

}  // namespace

std::vector<Index> find_fold_overs(const Mesh& surface, const Normals& normals, double distance,
                                   int threads) {
  const Index n = surface.num_faces();
  std::vector<char> folded(n, 0);
  parallel_for(n, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const Vec3& own = normals.faces[f];
      if (own == Vec3(0.0)) continue;
      folded[f] = glm::dot(offset_copy_normal(surface, normals, f, distance), own) <= 0.0 ||
                  glm::dot(offset_copy_normal(surface, normals, f, -distance), own) <= 0.0;
    }
  });
  // The second rule, per edge: a face whose copy has passed through its neighbour's across an edge.
  std::vector<char> edge_folded(surface.num_edges(), 0);
  parallel_for(surface.num_edges(), threads, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e) edge_folded[e] = edge_folds(surface, normals, e, distance);
  });
  for (Index e = 0; e < surface.num_edges(); ++e)
    if (edge_folded[e])
      for (const Index f : surface.edge(e).faces) folded[f] = 1;
  std::vector<Index> faces;
  for (Index f = 0; f < n; ++f)
    if (folded[f]) faces.push_back(f);
  return faces;
}

}  // namespace nome
