#include <algorithm>

#include "nome/mesh/mesh.hpp"
#include "ops/large_buffer.hpp"

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
  resize_on_huge_pages(m.corner_faces_, m.corner_vertices_.size());
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

}  // namespace nome
