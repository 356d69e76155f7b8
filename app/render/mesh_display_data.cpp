#include "render/mesh_display_data.hpp"

#include <algorithm>
#include <cmath>

#include "nome/mesh/normals.hpp"
#include "nome/query/display_triangles.hpp"

namespace nome::render {
namespace {

std::uint8_t to_byte(float channel) {
  return std::uint8_t(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

MeshDisplayData build_display_data(const Mesh& mesh) {
  MeshDisplayData data;
  const Normals normals = compute_normals(mesh);
  const Index corners = mesh.num_corners();
  data.num_faces = mesh.num_faces();
  data.corner_positions.resize(corners);
  data.smooth_normals.resize(corners);
  data.flat_normals.resize(corners);
  data.corner_faces.resize(corners);
  for (Index c = 0; c < corners; ++c) {
    const Index v = mesh.corner_vertex(c), f = mesh.corner_face(c);
    data.corner_positions[c] = glm::vec3(mesh.position(v));
    data.flat_normals[c] = glm::vec3(normals.faces[f]);
    const Vec3 smooth = double(mesh.corner_sign(c)) * normals.vertices[v];
    // A vertex whose signed normals cancel (a pinch) shades with its face's normal instead.
    data.smooth_normals[c] = glm::vec3(smooth == Vec3(0.0) ? normals.faces[f] : smooth);
    data.corner_faces[c] = f;
  }
  // The same triangles the viewer picks on.
  const DisplayTriangles triangulation = display_triangles(mesh);
  data.triangles.reserve(triangulation.corners.size() * 3);
  for (const auto& t : triangulation.corners) data.triangles.insert(data.triangles.end(), t.begin(), t.end());

  data.vertex_positions.reserve(mesh.num_vertices());
  for (const Vec3& p : mesh.positions()) {
    data.vertex_positions.emplace_back(p);
    data.bounds.add(p);
  }
  auto add_edges = [&](auto keep) {
    SegmentRange range{std::uint32_t(data.segments.size() / 2), 0};
    for (const Edge& e : mesh.edges()) {
      if (!keep(e)) continue;
      data.segments.push_back(e.vertices[0]);
      data.segments.push_back(e.vertices[1]);
      ++range.count;
    }
    return range;
  };
  data.all_edges = add_edges([](const Edge&) { return true; });
  data.mobius_edges = add_edges([](const Edge& e) { return e.is_mobius; });
  data.border_edges = add_edges([](const Edge& e) { return e.is_boundary(); });

  data.face_colors.assign(mesh.num_faces(), {0, 0, 0, 0});
  const auto& colors = mesh.face_colors();
  for (Index f = 0; f < std::min<Index>(Index(colors.size()), mesh.num_faces()); ++f)
    data.face_colors[f] = {to_byte(colors[f].r), to_byte(colors[f].g), to_byte(colors[f].b), 255};
  return data;
}

}  // namespace nome::render
