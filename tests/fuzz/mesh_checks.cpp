#include "fuzz/mesh_checks.hpp"

#include <cmath>
#include <cstdlib>

#include "nome/error.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/normals.hpp"

namespace nome::fuzz {
namespace {

void require(bool condition) {
  if (!condition) std::abort();
}

}  // namespace

void check_downstream(const Mesh& mesh) {
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

void build_and_check(PolygonSoup soup) {
  try {
    check_downstream(build_mesh(std::move(soup)));
  } catch (const TopologyError&) {
  } catch (const InvalidInputError&) {
  }
}

}  // namespace nome::fuzz
