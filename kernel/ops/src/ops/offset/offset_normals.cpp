#include "nome/ops/offset_normals.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "nome/error.hpp"
#include "support/parallel_for.hpp"

namespace nome {

// Reductions without an early exit (they vectorise), each thread over a share of the corners and of the
// vertices: a slider's every tick asks again.
bool is_two_copy_offset(const Mesh& mesh, int threads) {
  if (mesh.num_boundary_loops() > 0) return false;
  const signed char* signs = mesh.corner_signs().data();
  const Index* fans = mesh.fan_corner_offsets().data();
  const std::uint64_t nc = mesh.num_corners(), nv = mesh.num_vertices();
  const Index parts = parallel_parts(mesh.num_corners(), threads);
  std::vector<char> is_two_copy(parts, 0);
  parallel_for(
      parts, int(parts),
      [&](Index begin, Index end) {
        for (Index part = begin; part < end; ++part) {
          const Index first_corner = Index(nc * part / parts), end_corner = Index(nc * (part + 1) / parts);
          const Index first_vertex = Index(nv * part / parts), end_vertex = Index(nv * (part + 1) / parts);
          signed char lowest_sign = 1;
          for (Index c = first_corner; c < end_corner; ++c) lowest_sign = std::min(lowest_sign, signs[c]);
          bool has_isolated_vertex = false;
          for (Index v = first_vertex; v < end_vertex; ++v) has_isolated_vertex |= fans[v] == fans[v + 1];
          is_two_copy[part] = lowest_sign > 0 && !has_isolated_vertex;
        }
      },
      1);
  return std::all_of(is_two_copy.begin(), is_two_copy.end(), [](char fits) { return fits != 0; });
}

bool offset_packed_normals(const Mesh& mesh, const Normals& normals, Buffer<PackedNormal>& faces,
                           Buffer<PackedNormal>& vertices, int threads) {
  const Index nf = mesh.num_faces(), nv = mesh.num_vertices();
  if (normals.faces.size() != nf || normals.vertices.size() != nv)
    throw InvalidInputError("offset_packed_normals: " + std::to_string(normals.faces.size()) + " face and " +
                            std::to_string(normals.vertices.size()) + " vertex normals for " +
                            std::to_string(nf) + " faces and " + std::to_string(nv) + " vertices");
  if (!is_two_copy_offset(mesh, threads)) return false;
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
