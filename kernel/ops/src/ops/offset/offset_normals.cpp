#include "nome/ops/offset_normals.hpp"

#include <algorithm>
#include <string>

#include "nome/error.hpp"
#include "support/parallel_for.hpp"

namespace nome {

// Reductions without an early exit (they vectorise): a slider's every tick asks again.
bool is_two_copy_offset(const Mesh& mesh) {
  if (mesh.num_boundary_loops() > 0) return false;
  signed char lowest_sign = 1;
  for (const signed char s : mesh.corner_signs()) lowest_sign = std::min(lowest_sign, s);
  const Index* fans = mesh.fan_corner_offsets().data();
  bool has_isolated_vertex = false;
  for (Index v = 0; v < mesh.num_vertices(); ++v) has_isolated_vertex |= fans[v] == fans[v + 1];
  return lowest_sign > 0 && !has_isolated_vertex;
}

bool offset_packed_normals(const Mesh& mesh, const Normals& normals, Buffer<PackedNormal>& faces,
                           Buffer<PackedNormal>& vertices, int threads) {
  const Index nf = mesh.num_faces(), nv = mesh.num_vertices();
  if (normals.faces.size() != nf || normals.vertices.size() != nv)
    throw InvalidInputError("offset_packed_normals: " + std::to_string(normals.faces.size()) + " face and " +
                            std::to_string(normals.vertices.size()) + " vertex normals for " +
                            std::to_string(nf) + " faces and " + std::to_string(nv) + " vertices");
  if (!is_two_copy_offset(mesh)) return false;
  resize_for_overwrite(faces, 2 * std::size_t(nf));
  resize_for_overwrite(vertices, 2 * std::size_t(nv));
  // Faces are the positive copies, then the negative ones (reversed); v+ is vertex 2v, v- 2v + 1.
  parallel_for(nf, threads, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f) {
      const PackedNormal n = pack_normal(glm::vec3(normals.faces[f]));
      faces[f] = n;
      faces[nf + f] = negated(n);
    }
  });
  parallel_for(nv, threads, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v) {
      const PackedNormal n = pack_normal(glm::vec3(normals.vertices[v]));
      vertices[2 * std::size_t(v)] = n;
      vertices[2 * std::size_t(v) + 1] = negated(n);
    }
  });
  return true;
}

}  // namespace nome
