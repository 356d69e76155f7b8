#include "render/mesh_display_data.hpp"

#include <algorithm>
#include <cmath>

#include "nome/query/display_triangles.hpp"

namespace nome::render {
namespace {

std::uint8_t to_byte(float channel) {
  return std::uint8_t(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

void to_floats(const Buffer<Vec3>& from, Buffer<glm::vec3>& to) {
  resize_for_overwrite(to, from.size());
  std::transform(from.begin(), from.end(), to.begin(), [](const Vec3& v) { return glm::vec3(v); });
}

}  // namespace

DisplayTopology build_display_topology(const Mesh& mesh) {
  DisplayTopology data;
  const Index corners = mesh.num_corners();
  data.num_faces = mesh.num_faces();
  data.num_vertices = mesh.num_vertices();
  data.corner_vertices.resize(corners);
  data.corner_faces.resize(corners);
  for (Index c = 0; c < corners; ++c) {
    data.corner_vertices[c] = mesh.corner_vertex(c) | (mesh.corner_sign(c) < 0 ? corner_sign_bit : 0u);
    data.corner_faces[c] = mesh.corner_face(c);
  }
  // The same triangles the viewer picks on.
  const DisplayTriangles triangulation = display_triangles(mesh);
  data.triangles.reserve(triangulation.corners.size() * 3);
  for (const auto& t : triangulation.corners) data.triangles.insert(data.triangles.end(), t.begin(), t.end());
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
  return data;
}

void build_display_positions(const Mesh& mesh, Normals& normals, DisplayPositions& out) {
  compute_normals(mesh, normals);
  to_floats(mesh.positions(), out.vertices);
  to_floats(normals.vertices, out.vertex_normals);
  to_floats(normals.faces, out.face_normals);
  out.bounds = BoundingBox::of(mesh.positions());
}

std::vector<std::array<std::uint8_t, 4>> display_face_colors(const Mesh& mesh) {
  std::vector<std::array<std::uint8_t, 4>> out(mesh.num_faces(), {0, 0, 0, 0});
  const auto& colors = mesh.face_colors();
  for (Index f = 0; f < std::min<Index>(Index(colors.size()), mesh.num_faces()); ++f)
    out[f] = {to_byte(colors[f].r), to_byte(colors[f].g), to_byte(colors[f].b), 255};
  return out;
}

MeshDisplayData build_display_data(const Mesh& mesh) {
  MeshDisplayData data;
  data.topology = std::make_shared<const DisplayTopology>(build_display_topology(mesh));
  Normals normals;
  auto positions = std::make_shared<DisplayPositions>();
  build_display_positions(mesh, normals, *positions);
  data.positions = std::move(positions);
  data.face_colors = display_face_colors(mesh);
  return data;
}

}  // namespace nome::render
