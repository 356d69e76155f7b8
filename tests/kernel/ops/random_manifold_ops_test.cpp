#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

#include "nome/mesh/topology_report.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/brute_force_topology.hpp"
#include "support/random_manifold.hpp"

using namespace nome;

namespace {

// The same polygons with the vertices renumbered by `perm`, each face's corners rotated and some faces
// reversed: the same surface, described differently.
PolygonSoup redescribed(const PolygonSoup& soup, const std::vector<Index>& perm, std::mt19937& rng) {
  PolygonSoup out;
  out.positions.resize(soup.positions.size());
  for (Index v = 0; v < soup.num_vertices(); ++v) out.positions[perm[v]] = soup.positions[v];
  std::bernoulli_distribution reverse(0.4);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    std::vector<Index> vs;
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c)
      vs.push_back(perm[soup.face_vertices[c]]);
    std::rotate(vs.begin(), vs.begin() + std::uniform_int_distribution<size_t>(0, vs.size() - 1)(rng),
                vs.end());
    if (reverse(rng)) std::reverse(vs.begin(), vs.end());
    out.add_face(vs);
  }
  return out;
}

bool close(const Vec3& a, const Vec3& b) {
  const double scale = 1.0 + std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
  return std::abs(a.x - b.x) <= 1e-12 * scale && std::abs(a.y - b.y) <= 1e-12 * scale &&
         std::abs(a.z - b.z) <= 1e-12 * scale;
}

Index edge_between(const Mesh& m, Index a, Index b) {
  for (Index e : m.vertex_edges(a))
    if (m.edge(e).other_vertex(a) == b) return e;
  return no_index;
}

void check_subdivision_and_offset(unsigned i, const test::RandomManifoldOptions& options = {}) {
  const unsigned seed = test::seed_base() + i;
  INFO("seed " << seed << " (NOME_SEED=" << test::seed_base() << ")");
  std::mt19937 rng{seed};
  const test::RandomManifold generated = test::random_manifold(rng, options);
  const Mesh base = build_mesh(generated.soup);
  const TopologyReport before = topology_report(base);

  // phase: every level keeps chi, orientability and borders of every part, and is a manifold by the
  // brute-force count too.
  Mesh level = base;
  for (int k = 1; k <= 2; ++k) {
    INFO("level " << k);
    const Index quads = level.num_corners();
    level = subdivide(level, {1, SubdivisionRule::classic});
    CHECK(level.num_faces() == quads);
    const TopologyReport after = topology_report(level);
    const test::BruteForceTopology brute = test::brute_force_topology(to_soup(level));
    REQUIRE(brute.is_manifold);
    CHECK(brute.report.chi == after.chi);
    CHECK(brute.report.mobius_edges == after.mobius_edges);
    REQUIRE(after.components.size() == before.components.size());
    for (size_t i = 0; i < after.components.size(); ++i) {
      CHECK(after.components[i].chi == before.components[i].chi);
      CHECK(after.components[i].orientable == before.components[i].orientable);
      CHECK(after.components[i].borders == before.components[i].borders);
      CHECK(after.components[i].genus == before.components[i].genus);
    }
  }

  // phase: positions do not depend on numbering, corner order or orientation. Children are numbered
  // face points, then edge points, then vertex points (Refinement's contract).
  std::vector<Index> perm(base.num_vertices());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  const Mesh other = build_mesh(redescribed(generated.soup, perm, rng));
  for (SubdivisionRule rule : {SubdivisionRule::classic, SubdivisionRule::report}) {
    const Mesh a = subdivide(base, {1, rule}), b = subdivide(other, {1, rule});
    const Index nf = base.num_faces(), ne = base.num_edges();
    bool same = true;
    for (Index f = 0; f < nf; ++f) same = same && close(a.position(f), b.position(f));
    for (Index e = 0; e < ne; ++e) {
      const Edge& edge = base.edge(e);
      const Index e_other = edge_between(other, perm[edge.vertices[0]], perm[edge.vertices[1]]);
      REQUIRE(e_other != no_index);
      same = same && close(a.position(nf + e), b.position(nf + e_other));
    }
    for (Index v = 0; v < base.num_vertices(); ++v)
      same = same && close(a.position(nf + ne + v), b.position(nf + ne + perm[v]));
    CHECK(same);
  }

  // phase: the offset of the surface and of its first level is a closed, orientable, consistently
  // oriented manifold with twice its chi.
  const Mesh* surfaces[] = {&base, &level};
  for (const Mesh* surface : surfaces) {
    const Mesh solid = offset(*surface, OffsetOptions{0.01});
    const TopologyReport r = topology_report(solid);
    const test::BruteForceTopology brute = test::brute_force_topology(to_soup(solid));
    REQUIRE(brute.is_manifold);
    CHECK(r.borders == 0);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
    CHECK(brute.report.mobius_edges == 0);
    CHECK(r.chi == 2 * topology_report(*surface).chi);
    CHECK(brute.report.chi == r.chi);
  }
}

}  // namespace

TEST_CASE("random 2-manifolds: Catmull-Clark keeps the topology, ignores the description, offsets are solids",
          "[kernel]") {
  for (unsigned seed = 1; seed <= 60; ++seed) check_subdivision_and_offset(seed);
}

TEST_CASE("random 2-manifolds of up to 120 polygons: Catmull-Clark and offset keep their topology",
          "[kernel]") {
  for (unsigned seed = 1; seed <= 3; ++seed) check_subdivision_and_offset(seed, {.max_polygons = 120});
}

TEST_CASE("soak: Catmull-Clark and offset on 10,000 random 2-manifolds", "[.][soak]") {
  for (unsigned seed = 1; seed <= 10000; ++seed) check_subdivision_and_offset(seed);
}
