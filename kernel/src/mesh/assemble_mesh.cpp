#include <algorithm>

#include "nome/mesh/mesh.hpp"

namespace nome {

Mesh assemble_mesh(MeshArrays arrays) {
  Mesh m;
  m.positions_ = std::move(arrays.positions);
  m.face_offsets_ = std::move(arrays.face_offsets);
  m.corner_vertices_ = std::move(arrays.corner_vertices);
  m.corner_edges_ = std::move(arrays.corner_edges);
  m.corner_signs_ = std::move(arrays.corner_signs);
  m.edges_ = std::move(arrays.edges);
  m.fan_corner_offsets_ = std::move(arrays.fan_corner_offsets);
  m.fan_corners_ = std::move(arrays.fan_corners);
  m.fan_edge_offsets_ = std::move(arrays.fan_edge_offsets);
  m.fan_edges_ = std::move(arrays.fan_edges);
  m.face_colors_ = std::move(arrays.face_colors);
  m.corner_faces_ = std::move(arrays.corner_faces);
  resize_for_overwrite(m.corner_faces_, m.corner_vertices_.size());
  for (Index f = 0; f < m.num_faces(); ++f)
    std::fill(m.corner_faces_.begin() + m.face_offsets_[f], m.corner_faces_.begin() + m.face_offsets_[f + 1],
              f);
  m.find_boundary_loops();
  if (arrays.face_components.empty()) {
    m.find_components();
  } else {
    m.face_components_ = std::move(arrays.face_components);
    m.num_components_ = arrays.num_components;
  }
  return m;
}

// Every array comes out as a default MeshArrays has it (empty, the offsets {0}), only its block is kept.
MeshArrays take_arrays(Mesh&& mesh) {
  MeshArrays a;
  a.corner_faces = std::move(mesh.corner_faces_);
  a.positions = std::move(mesh.positions_);
  a.face_offsets = std::move(mesh.face_offsets_);
  a.corner_vertices = std::move(mesh.corner_vertices_);
  a.corner_edges = std::move(mesh.corner_edges_);
  a.corner_signs = std::move(mesh.corner_signs_);
  a.edges = std::move(mesh.edges_);
  a.fan_corner_offsets = std::move(mesh.fan_corner_offsets_);
  a.fan_corners = std::move(mesh.fan_corners_);
  a.fan_edge_offsets = std::move(mesh.fan_edge_offsets_);
  a.fan_edges = std::move(mesh.fan_edges_);
  a.face_components = std::move(mesh.face_components_);
  a.face_colors = std::move(mesh.face_colors_);
  mesh = Mesh();
  for (Buffer<Index>* b : {&a.corner_faces, &a.corner_vertices, &a.corner_edges, &a.fan_corners, &a.fan_edges,
                           &a.face_components})
    b->clear();
  for (Buffer<Index>* b : {&a.face_offsets, &a.fan_corner_offsets, &a.fan_edge_offsets}) b->assign(1, 0);
  a.positions.clear();
  a.corner_signs.clear();
  a.edges.clear();
  a.face_colors.clear();
  return a;
}

}  // namespace nome
