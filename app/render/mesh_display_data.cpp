#include "render/mesh_display_data.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/query/display_triangles.hpp"
#include "nome/stop_token.hpp"
#include "nome/thread_support.hpp"

namespace nome::render {
namespace {

std::uint8_t to_byte(float channel) {
  return std::uint8_t(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

// The GL vertices of a DisplayTopology: a mesh vertex's own, its turned-round copy for corners of
// negative sign, and repeats where a face finds no vertex free to carry its id.
class GlVertices {
 public:
  GlVertices(const Mesh& mesh, DisplayTopology& out)
      : mesh_(mesh), out_(out), negative_(mesh.num_vertices(), no_gl_vertex) {
    out_.vertex_faces.assign(mesh.num_vertices(), no_face);
  }
  ~GlVertices() {
    // Vertices that start no triangle: their face is never read.
    std::replace(out_.vertex_faces.begin(), out_.vertex_faces.end(), no_face, 0u);
  }
  GlVertices(const GlVertices&) = delete;
  GlVertices& operator=(const GlVertices&) = delete;

  std::uint32_t of_corner(Index c) {
    const Index v = mesh_.corner_vertex(c);
    if (mesh_.corner_sign(c) > 0) return v;
    if (negative_[v] == no_gl_vertex) negative_[v] = add(v | corner_sign_bit);
    return negative_[v];
  }
  // The vertex that carries face f in place of u: u if it carries f already or nothing yet, else a repeat.
  std::uint32_t carrier(std::uint32_t u, Index f) {
    if (out_.vertex_faces[u] == no_face) out_.vertex_faces[u] = f;
    if (out_.vertex_faces[u] == f) return u;
    const std::uint32_t repeat = add(key(u));
    out_.vertex_faces[repeat] = f;
    return repeat;
  }

 private:
  static constexpr std::uint32_t no_gl_vertex = 0xffffffffu, no_face = 0xffffffffu;
  std::uint32_t key(std::uint32_t u) const {
    return u < out_.num_vertices ? u : out_.extra_vertices[u - out_.num_vertices];
  }
  std::uint32_t add(std::uint32_t key) {
    out_.extra_vertices.push_back(key);
    out_.vertex_faces.push_back(no_face);
    return out_.num_gl_vertices() - 1;
  }

  const Mesh& mesh_;
  DisplayTopology& out_;
  std::vector<std::uint32_t> negative_;  // per mesh vertex, its turned-round copy
};

// The triangles over GL vertices, each ending with a vertex that carries its face's id (GLES takes flat
// inputs from the last vertex): the face's first corner for the triangles that start there (all of a
// fan's), else the triangle's own first vertex, repeated where it carries another face. The corners turn
// once, keeping the winding.
void provoking_triangles(const Mesh& mesh, const DisplayTriangles& triangles, DisplayTopology& out) {
  GlVertices vertices(mesh, out);
  resize_for_overwrite(out.triangles, std::size_t(triangles.size()) * 3);
  std::uint32_t* gl = out.triangles.data();
  for (Index t = 0; t < triangles.size();) {
    const Index f = triangles.faces[t];
    const Index start = triangles.corners[t][0];
    const std::uint32_t apex = vertices.carrier(vertices.of_corner(start), f);
    for (; t < triangles.size() && triangles.faces[t] == f; ++t, gl += 3) {
      const auto& c = triangles.corners[t];
      gl[0] = vertices.of_corner(c[1]);
      gl[1] = vertices.of_corner(c[2]);
      gl[2] = c[0] == start ? apex : vertices.carrier(vertices.of_corner(c[0]), f);
    }
  }
}

// The segments of all edges, then the Möbius ones, then the border ones.
void edge_segments(const Mesh& mesh, DisplayTopology& out) {
  std::vector<std::uint32_t> mobius, border;
  const Index edges = mesh.num_edges();
  resize_for_overwrite(out.segments, 2 * std::size_t(edges));
  for (Index i = 0; i < edges; ++i) {
    const Edge& e = mesh.edge(i);
    out.segments[2 * std::size_t(i)] = e.vertices[0];
    out.segments[2 * std::size_t(i) + 1] = e.vertices[1];
    if (e.is_mobius) mobius.insert(mobius.end(), {e.vertices[0], e.vertices[1]});
    if (e.is_boundary()) border.insert(border.end(), {e.vertices[0], e.vertices[1]});
  }
  out.all_edges = {0, edges};
  out.mobius_edges = {edges, std::uint32_t(mobius.size() / 2)};
  out.border_edges = {out.mobius_edges.first + out.mobius_edges.count, std::uint32_t(border.size() / 2)};
  out.segments.insert(out.segments.end(), mobius.begin(), mobius.end());
  out.segments.insert(out.segments.end(), border.begin(), border.end());
}

// Positions [begin, end) rounded to single precision, and their box.
BoundingBox round_positions(const Buffer<Vec3>& positions, Buffer<glm::vec3>& out, std::size_t begin,
                            std::size_t end) {
  BoundingBox box;
  for (std::size_t i = begin; i < end; ++i) {
    out[i] = glm::vec3(positions[i]);
    box.add(positions[i]);
  }
  return box;
}

}  // namespace

DisplayTopology build_display_topology(const Mesh& mesh, int threads) {
  DisplayTopology data;
  data.num_faces = mesh.num_faces();
  data.num_vertices = mesh.num_vertices();
  // The same triangles the viewer picks on.
  provoking_triangles(mesh, display_triangles(mesh, threads), data);
  edge_segments(mesh, data);
  return data;
}

void build_display_positions(const Mesh& mesh, const DisplayTopology& topology, DisplayPositions& out,
                             int threads, DisplayNormals normals) {
  if (normals == DisplayNormals::computed) {
    compute_packed_face_normals(mesh, out.face_normals, threads);
  } else if (out.face_normals.size() != mesh.num_faces() ||
             out.vertex_normals.size() != mesh.num_vertices()) {
    throw InvalidInputError("build_display_positions: " + std::to_string(out.face_normals.size()) +
                            " face and " + std::to_string(out.vertex_normals.size()) +
                            " vertex normals given for " + std::to_string(mesh.num_faces()) + " faces and " +
                            std::to_string(mesh.num_vertices()) + " vertices");
  }
  const Buffer<Vec3>& positions = mesh.positions();
  const Buffer<std::uint32_t>& extra = topology.extra_vertices;
  resize_for_overwrite(out.vertices, positions.size());
  resize_for_overwrite(out.extra_vertices, extra.size());
  resize_for_overwrite(out.extra_normals, extra.size());
  // Where no helper thread can start, this thread rounds all positions: the same bounds as two halves.
  const bool is_large = threads > 1 && positions.size() >= (1u << 16) && can_start_threads();
  if (normals == DisplayNormals::computed) {
    // A large mesh's positions are rounded beside the vertex normals' gather.
    jthread helper;
    if (is_large)
      helper = jthread([&] { out.bounds = round_positions(positions, out.vertices, 0, positions.size()); });
    else
      out.bounds = round_positions(positions, out.vertices, 0, positions.size());
    compute_packed_vertex_normals(mesh, out.face_normals, out.vertex_normals, threads);
  } else if (is_large) {
    // Only the rounding is left: half each.
    const std::size_t half = positions.size() / 2;
    BoundingBox second;
    {
      const jthread helper(
          [&] { second = round_positions(positions, out.vertices, half, positions.size()); });
      out.bounds = round_positions(positions, out.vertices, 0, half);
    }
    out.bounds.add(second.min);
    out.bounds.add(second.max);
  } else {
    out.bounds = round_positions(positions, out.vertices, 0, positions.size());
  }
  for (std::size_t i = 0; i < extra.size(); ++i) {
    const std::uint32_t v = extra[i] & ~corner_sign_bit;
    const PackedNormal n = out.vertex_normals[v];
    out.extra_vertices[i] = out.vertices[v];
    out.extra_normals[i] = extra[i] & corner_sign_bit ? negated(n) : n;
  }
}

std::vector<std::array<std::uint8_t, 4>> display_face_colors(const Mesh& mesh) {
  const Column<Color>* colors = find_colors(mesh.face_attributes());
  std::vector<std::array<std::uint8_t, 4>> out;
  if (!colors || colors->values().empty()) return out;
  out.assign(mesh.num_faces(), {0, 0, 0, 0});
  const std::vector<Color>& values = colors->values();
  for (Index f = 0; f < std::min<Index>(Index(values.size()), mesh.num_faces()); ++f)
    if (values[f] != no_face_color)
      out[f] = {to_byte(values[f].r), to_byte(values[f].g), to_byte(values[f].b), 255};
  return out;
}

MeshDisplayData build_display_data(const Mesh& mesh) {
  MeshDisplayData data;
  data.topology = std::make_shared<const DisplayTopology>(build_display_topology(mesh));
  auto positions = std::make_shared<DisplayPositions>();
  build_display_positions(mesh, *data.topology, *positions);
  data.positions = std::move(positions);
  data.face_colors = display_face_colors(mesh);
  return data;
}

}  // namespace nome::render
