#include "nome/query/fold_overs.hpp"

#include <glm/geometric.hpp>

#include "ops/parallel_for.hpp"

namespace nome {
namespace {

// Newell's normal of face f with each corner moved by side * d * s * n_v: one of the offset's two copies.
Vec3 offset_copy_normal(const Mesh& mesh, const Normals& normals, Index f, double shift) {
  Vec3 normal(0.0);
  const Index first = mesh.face_first_corner(f), degree = mesh.face_degree(f);
  auto moved = [&](Index i) {
    const Index c = first + i % degree;
    const Index v = mesh.corner_vertex(c);
    return mesh.position(v) + (shift * mesh.corner_sign(c)) * normals.vertices[v];
  };
  Vec3 current = moved(0);
  for (Index i = 0; i < degree; ++i) {
    const Vec3 next = moved(i + 1);
    normal += glm::cross(current, next);
    current = next;
  }
  return normal;
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
  std::vector<Index> faces;
  for (Index f = 0; f < n; ++f)
    if (folded[f]) faces.push_back(f);
  return faces;
}

}  // namespace nome
