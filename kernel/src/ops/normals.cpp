#include "nome/ops/normals.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace nome {

Vec3 face_area_normal(const Mesh& mesh, Index f) {
  const auto vs = mesh.face_vertices(f);
  Vec3 n(0.0);
  const Vec3* a = &mesh.position(vs.back());
  for (Index v : vs) {
    const Vec3& b = mesh.position(v);
    n += Vec3((a->y - b.y) * (a->z + b.z), (a->z - b.z) * (a->x + b.x), (a->x - b.x) * (a->y + b.y));
    a = &b;
  }
  return n;
}

Normals compute_normals(const Mesh& mesh) {
  Normals out;
  out.faces.resize(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Vec3 n = face_area_normal(mesh, f);
    const double len = glm::length(n);
    // Relative threshold: area against the squared length of the face's longest side.
    double extent_squared = 0.0;
    const auto vs = mesh.face_vertices(f);
    const Vec3* a = &mesh.position(vs.back());
    for (Index v : vs) {
      const Vec3 side = mesh.position(v) - *a;
      extent_squared = std::max(extent_squared, glm::dot(side, side));
      a = &mesh.position(v);
    }
    if (!(len > 1e-14 * extent_squared) || extent_squared == 0.0) {
      out.faces[f] = Vec3(0.0);
      out.degenerate_faces.push_back(f);
    } else {
      out.faces[f] = n / len;
    }
  }
  out.vertices.resize(mesh.num_vertices());
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    Vec3 sum(0.0);
    for (Index c : mesh.vertex_corners(v))
      sum += double(mesh.corner_sign(c)) * out.faces[mesh.corner_face(c)];
    const double len = glm::length(sum);
    if (len > 1e-12) {
      out.vertices[v] = sum / len;
    } else {
      out.vertices[v] = Vec3(0.0);
      if (!mesh.is_isolated_vertex(v)) out.degenerate_vertices.push_back(v);
    }
  }
  return out;
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
