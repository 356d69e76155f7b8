#include <cstdlib>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "fuzz/polygon_soup_bytes.hpp"
#include "nome/error.hpp"
#include "nome/mesh/topology_report.hpp"
#include "support/brute_force_topology.hpp"

namespace {

bool is_same_report(const nome::TopologyReport& a, const nome::TopologyReport& b) {
  if (a.vertices != b.vertices || a.edges != b.edges || a.faces != b.faces || a.orientable != b.orientable ||
      a.borders != b.borders || a.mobius_edges != b.mobius_edges ||
      a.isolated_vertices != b.isolated_vertices || a.components.size() != b.components.size())
    return false;
  for (size_t i = 0; i < a.components.size(); ++i) {
    const auto &p = a.components[i], &q = b.components[i];
    if (p.vertices != q.vertices || p.edges != q.edges || p.faces != q.faces ||
        p.orientable != q.orientable || p.borders != q.borders || p.genus != q.genus ||
        p.mobius_edges != q.mobius_edges)
      return false;
  }
  return true;
}

}  // namespace

// Differential: build_mesh accepts exactly the soups the brute-force routine finds manifold, with the
// same topology report; then everything downstream runs on what it accepted.
NOME_FUZZ_TARGET(polygon_soup) {
  const nome::PolygonSoup soup = nome::fuzz::polygon_soup_from_bytes(data, size);
  const nome::test::BruteForceTopology brute = nome::test::brute_force_topology(soup);
  nome::Mesh mesh;
  try {
    mesh = nome::build_mesh(soup);
  } catch (const nome::TopologyError&) {
    if (brute.is_manifold) std::abort();
    return 0;
  }
  if (!brute.is_manifold || !is_same_report(nome::topology_report(mesh), brute.report)) std::abort();
  nome::fuzz::check_downstream(mesh);
  return 0;
}
