#include "mesh/normal_passes.hpp"
#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"

namespace nome {

void compute_packed_normals(const Mesh& mesh, Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                            int threads) {
  compute_packed_face_normals(mesh, faces, threads);
  compute_packed_vertex_normals(mesh, faces, vertices, threads);
}

void compute_packed_face_normals(const Mesh& mesh, Buffer<PackedNormal>& faces, int threads) {
  resize_for_overwrite(faces, mesh.num_faces());
  std::vector<Index> degenerate;
  normal_passes::face_normals(mesh, faces.data(), degenerate, threads);
}

void compute_packed_vertex_normals(const Mesh& mesh, std::span<const PackedNormal> faces,
                                   Buffer<PackedNormal>& vertices, int threads) {
  if (faces.size() != mesh.num_faces())
    throw InvalidInputError("compute_packed_vertex_normals: " + std::to_string(faces.size()) +
                            " face normals for " + std::to_string(mesh.num_faces()) + " faces");
  resize_for_overwrite(vertices, mesh.num_vertices());
  std::vector<Index> degenerate;
  normal_passes::vertex_normals(mesh, faces.data(), vertices.data(), degenerate, threads);
}

}  // namespace nome
