#include "nome/mesh/mesh.hpp"

namespace nome {

Mesh assemble_mesh(MeshArrays arrays) {
  Mesh m;
  const bool has_components = !arrays.face_components.empty();
  m.arrays_ = std::move(arrays);
  m.find_corner_faces();
  m.find_boundary_loops();
  if (!has_components) m.find_components();
  return m;
}

// Every array comes out as a default MeshArrays has it (empty, the offsets {0}), only its block is kept.
MeshArrays take_arrays(Mesh&& mesh) {
  MeshArrays a = std::move(mesh.arrays_);
  mesh = Mesh();
  for (Buffer<Index>* b : {&a.corner_faces, &a.corner_vertices, &a.corner_edges, &a.fan_corners, &a.fan_edges,
                           &a.face_components})
    b->clear();
  for (Buffer<Index>* b : {&a.face_offsets, &a.fan_corner_offsets, &a.fan_edge_offsets}) b->assign(1, 0);
  a.positions.clear();
  a.corner_signs.clear();
  a.edges.clear();
  a.num_components = 0;
  a.face_attributes = {};
  a.edge_sharpness.clear();
  a.vertex_sharpness.clear();
  a.face_holes.clear();
  return a;
}

}  // namespace nome
