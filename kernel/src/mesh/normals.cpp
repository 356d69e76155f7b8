#include "nome/mesh/normals.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace nome {

namespace {

// Newell's term of the polygon side a -> b.
Vec3 newell_term(const Vec3& a, const Vec3& b) {
  return Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
}

}  // namespace

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

void compute_normals(const Mesh& mesh, Normals& out) {
  // Raw arrays in the loops: these run over every face and vertex of meshes of millions of faces.
  const Vec3* p = mesh.positions().data();
  const Index* offsets = mesh.face_offsets().data();
  const Index* corners = mesh.corner_vertices().data();
  const signed char* signs = mesh.corner_signs().data();
  resize_for_overwrite(out.faces, mesh.num_faces());
  out.vertices.assign(mesh.num_vertices(), Vec3(0.0));
  out.degenerate_faces.clear();
  out.degenerate_vertices.clear();
  // One pass over the faces, in corner order: each face's normal is added to its vertices' sums with its
  // corner's sign right away (streaming reads; gathering over the fans instead reads three arrays at
  // random per corner).
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    // Newell's normal and the longest side in one walk round the face. The degeneracy threshold is
    // relative: area against the squared length of the longest side.
    Vec3 n(0.0);
    double extent_squared = 0.0;
    const Vec3* a = &p[corners[offsets[f + 1] - 1]];
    for (Index c = offsets[f]; c < offsets[f + 1]; ++c) {
      const Vec3& b = p[corners[c]];
      n += newell_term(*a, b);
      const Vec3 side = b - *a;
      extent_squared = std::max(extent_squared, glm::dot(side, side));
      a = &b;
    }
    const double len = glm::length(n);
    if (!(len > 1e-14 * extent_squared) || extent_squared == 0.0) {
      out.faces[f] = Vec3(0.0);
      out.degenerate_faces.push_back(f);
      continue;
    }
    n *= 1.0 / len;
    out.faces[f] = n;
    for (Index c = offsets[f]; c < offsets[f + 1]; ++c) {
      Vec3& sum = out.vertices[corners[c]];
      if (signs[c] > 0)
        sum += n;
      else
        sum -= n;
    }
  }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    Vec3& n = out.vertices[v];
    const double len = glm::length(n);
    if (len > 1e-12) {
      n *= 1.0 / len;
    } else {
      n = Vec3(0.0);
      if (!mesh.is_isolated_vertex(v)) out.degenerate_vertices.push_back(v);
    }
  }
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
