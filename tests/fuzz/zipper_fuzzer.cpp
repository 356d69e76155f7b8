#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "fuzz/polygon_soup_bytes.hpp"
#include "nome/error.hpp"
#include "nome/ops/zipper.hpp"

namespace {

// A selection on loop `loop` from bytes: its start, and its end (the same vertex: the whole loop).
nome::BorderSelection selection_from(const nome::Mesh& mesh, nome::Index loop, const uint8_t* b, bool whole) {
  const auto vertices = mesh.loop_vertices(loop);
  const nome::Index n = nome::Index(vertices.size());
  const nome::Index start = b[0] % n, end = whole ? start : (start + 1 + b[1] % (n - 1)) % n;
  return {vertices[start], vertices[end], bool(b[2] & 1)};
}

}  // namespace

// Random border pairs of a random mesh (the first seven bytes choose two different boundary loops, whole
// or a segment of each, and the directions; the rest is the soup): the strip has the counts it reports,
// proper polygons, every border edge of the first selection in exactly one strip face, and whatever mesh
// the strip and the faces make together, when it is a 2-manifold, passes the downstream checks.
NOME_FUZZ_TARGET(zipper) {
  if (size < 7) return 0;
  nome::Mesh mesh;
  try {
    mesh = nome::build_mesh(nome::fuzz::polygon_soup_from_bytes(data + 7, size - 7));
  } catch (const nome::TopologyError&) {
    return 0;
  }
  const nome::Index loops = mesh.num_boundary_loops();
  if (loops < 2) return 0;
  const nome::Index la = data[0] % loops, lb = (la + 1 + data[1] % (loops - 1)) % loops;
  const bool whole = data[6] & 1;
  if (!whole && (mesh.loop_vertices(la).size() < 2 || mesh.loop_vertices(lb).size() < 2)) return 0;
  const nome::BorderSelection a = selection_from(mesh, la, data + 2, whole);
  const nome::BorderSelection b = selection_from(mesh, lb, data + 4, whole);
  const nome::ZipperFaces strip = nome::zipper_borders(mesh, a, b);
  if (strip.faces.size() != size_t(strip.quads) + strip.triangles) std::abort();
  std::map<std::pair<nome::Index, nome::Index>, int> edge_uses;
  for (const auto& face : strip.faces) {
    if (face.size() != 3 && face.size() != 4) std::abort();
    if (std::set<nome::Index>(face.begin(), face.end()).size() != face.size()) std::abort();
    for (size_t k = 0; k < face.size(); ++k) {
      const nome::Index u = face[k], v = face[(k + 1) % face.size()];
      ++edge_uses[{std::min(u, v), std::max(u, v)}];
    }
  }
  const std::vector<nome::Index> chain = nome::border_chain(mesh, a);
  for (size_t k = 0; k + 1 < chain.size(); ++k)
    if (edge_uses[{std::min(chain[k], chain[k + 1]), std::max(chain[k], chain[k + 1])}] != 1) std::abort();

  nome::PolygonSoup joined = nome::to_soup(mesh);
  for (const auto& face : strip.faces) joined.add_face(face);
  nome::fuzz::build_and_check(std::move(joined));
  return 0;
}
