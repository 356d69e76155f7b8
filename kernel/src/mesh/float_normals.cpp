#include "mesh/normal_passes.hpp"
#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"

namespace nome {

// Single-precision sums: half the bytes of the scatter, and no double arrays to round afterwards.
void compute_float_normals(const Mesh& mesh, Buffer<glm::vec3>& faces, Buffer<glm::vec3>& vertices,
                           int threads) {
  compute_float_face_normals(mesh, faces, threads);
  compute_float_vertex_normals(mesh, faces, vertices, threads);
}

void compute_float_face_normals(const Mesh& mesh, Buffer<glm::vec3>& faces, int threads) {
  resize_for_overwrite(faces, mesh.num_faces());
  std::vector<Index> degenerate;
  normal_passes::face_normals(mesh, faces.data(), degenerate, threads);
}

void compute_float_vertex_normals(const Mesh& mesh, std::span<const glm::vec3> faces,
                                  Buffer<glm::vec3>& vertices, int threads) {
  if (faces.size() != mesh.num_faces())
    throw InvalidInputError("compute_float_vertex_normals: " + std::to_string(faces.size()) +
                            " face normals for " + std::to_string(mesh.num_faces()) + " faces");
  resize_for_overwrite(vertices, mesh.num_vertices());
  std::vector<Index> degenerate;
  normal_passes::vertex_normals(mesh, faces.data(), vertices.data(), degenerate, threads);
}

}  // namespace nome
