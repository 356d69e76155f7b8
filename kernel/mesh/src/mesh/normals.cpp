#include "nome/mesh/normals.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "mesh/normal_passes.hpp"

namespace nome {

using normal_passes::newell_term;

Vec3 polygon_area_normal(std::span<const Index> vertices, std::span<const Vec3> positions) {
  Vec3 n(0.0);
  const Vec3* a = &positions[vertices.back()];
  for (Index v : vertices) {
    n += newell_term(*a, positions[v]);
    a = &positions[v];
  }
  return n;
}

Vec3 face_area_normal(const Mesh& mesh, Index f) {
  return polygon_area_normal(mesh.face_vertices(f), mesh.positions());
}

Normals compute_normals(const Mesh& mesh) {
  Normals out;
  compute_normals(mesh, out);
  return out;
}

void compute_normals(const Mesh& mesh, Normals& out, int threads) {
  resize_for_overwrite(out.faces, mesh.num_faces());
  resize_for_overwrite(out.vertices, mesh.num_vertices());
  normal_passes::face_normals(mesh, out.faces.data(), out.degenerate_faces, threads);
  normal_passes::vertex_normals(mesh, out.faces.data(), out.vertices.data(), out.degenerate_vertices,
                                threads);
}

std::string degeneracy_warning(const Mesh& mesh, const Normals& normals) {
  constexpr size_t max_named = 8;
  std::string out;
  auto list = [&](const std::vector<Index>& ids, const char* what, auto label) {
    if (ids.empty()) return;
    if (!out.empty()) out += "; ";
    out += std::to_string(ids.size()) + " " + what + ": ";
    for (size_t i = 0; i < std::min(ids.size(), max_named); ++i) out += (i ? ", " : "") + label(ids[i]);
    if (ids.size() > max_named) out += ", ...";
  };
  list(normals.degenerate_faces, "degenerate faces (zero area or coinciding vertices)",
       [&](Index f) { return mesh.face_label(f); });
  list(normals.degenerate_vertices, "vertices whose faces' normals cancel",
       [&](Index v) { return mesh.vertex_label(v); });
  if (!out.empty()) out += "; their normals are set to zero";
  return out;
}

}  // namespace nome
