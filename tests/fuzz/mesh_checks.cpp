#include "fuzz/mesh_checks.hpp"

#include "fuzz/fuzz_target.hpp"

#include <cmath>
#include <cstdlib>

#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/merge.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/brute_force_topology.hpp"

namespace nome::fuzz {
namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

// What must hold for any mesh: counts agree, normals are finite, the soup round trip rebuilds it.
void check_mesh(const Mesh& mesh) {
  const TopologyReport report = topology_report(mesh);
  require(report.vertices + report.isolated_vertices == mesh.num_vertices());
  require(report.edges == mesh.num_edges() && report.faces == mesh.num_faces());
  require(report.chi == (long long)report.vertices - report.edges + report.faces);
  const Normals normals = compute_normals(mesh);
  for (const Vec3& n : normals.vertices)
    require(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  const Mesh again = build_mesh(to_soup(mesh));
  require(again.num_edges() == mesh.num_edges() && again.num_boundary_loops() == mesh.num_boundary_loops());
}

}  // namespace

void check_downstream(const Mesh& mesh) {
  check_mesh(mesh);
  // Fuzzed positions lie on a coarse grid, so boundary merges happen often; whatever is glued must
  // still be a 2-manifold by the brute-force count.
  const MergeResult merged = merge_boundaries(mesh);
  check_mesh(merged.mesh);
  require(test::brute_force_topology(to_soup(merged.mesh)).is_manifold);

  // Catmull-Clark keeps every part's topology; the offset is a closed, orientable, consistently
  // oriented solid with twice the surface's chi.
  const TopologyReport before = topology_report(mesh);
  const Mesh smooth = subdivide(mesh, {1, SubdivisionRule::classic});
  check_mesh(smooth);
  const TopologyReport after = topology_report(smooth);
  require(after.components.size() == before.components.size());
  for (size_t i = 0; i < after.components.size(); ++i)
    require(after.components[i].chi == before.components[i].chi &&
            after.components[i].orientable == before.components[i].orientable &&
            after.components[i].borders == before.components[i].borders);
  const Mesh solid = offset(smooth, OffsetOptions{0.01});
  check_mesh(solid);
  const TopologyReport shell = topology_report(solid);
  require(shell.borders == 0 && shell.orientable && shell.mobius_edges == 0 && shell.chi == 2 * after.chi);
}

void require_located_refusal(const Error& error, std::string_view file) {
  const std::string_view message = error.what();
  require(dynamic_cast<const InvalidInputError*>(&error) == nullptr);
  require(message.substr(0, file.size()) == file && message.size() > file.size() &&
          message[file.size()] == ':');
}

void build_and_check(PolygonSoup soup) {
  Mesh mesh;
  try {
    mesh = build_mesh(std::move(soup));
  } catch (const TopologyError&) {
    return;
  }
  // Outside the try: an error thrown downstream of an accepted mesh is a bug.
  check_downstream(mesh);
}

}  // namespace nome::fuzz
