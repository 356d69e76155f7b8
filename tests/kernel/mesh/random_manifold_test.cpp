#include <catch2/catch.hpp>

#include <random>

#include "nome/error.hpp"
#include "nome/mesh/topology_report.hpp"
#include "support/brute_force_topology.hpp"
#include "support/random_manifold.hpp"
#include "support/same_report.hpp"

using namespace nome;

namespace {

// One random manifold: the brute-force routine agrees with how it was glued, the kernel agrees with
// the brute-force routine.
void check_random_manifold(unsigned i, const test::RandomManifoldOptions& options = {}) {
  const unsigned seed = test::seed_base() + i;
  INFO("seed " << seed << " (NOME_SEED=" << test::seed_base() << ")");
  std::mt19937 rng{seed};
  const test::RandomManifold m = test::random_manifold(rng, options);
  const test::BruteForceTopology brute = test::brute_force_topology(m.soup);
  INFO(brute.problem);
  REQUIRE(brute.is_manifold);
  REQUIRE(brute.report.components.size() == m.parts.size());
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const test::ExpectedPart& e = m.parts[i];
    const ComponentTopology& b = brute.report.components[i];
    INFO("part " << i);
    CHECK(b.vertices == e.vertices);
    CHECK(b.edges == e.edges);
    CHECK(b.faces == e.faces);
    CHECK(b.chi == e.chi);
    CHECK(b.orientable == e.orientable);
    CHECK(b.borders == e.borders);
  }
  test::check_same_report(topology_report(build_mesh(m.soup)), brute.report);
}

// One random corruption of a random manifold (two vertices pinched into one, a face added on random
// vertices, a face duplicated or dropped): the kernel refuses exactly what the brute-force routine
// finds non-manifold, and reports the same topology for the rest.
void check_corrupted_manifold(unsigned i, const test::RandomManifoldOptions& options = {}) {
  const unsigned seed = test::seed_base() + i;
  INFO("seed " << seed << " (NOME_SEED=" << test::seed_base() << ")");
  std::mt19937 rng{seed};
  PolygonSoup soup = test::random_manifold(rng, options).soup;
  std::uniform_int_distribution<Index> any_vertex(0, soup.num_vertices() - 1);
  std::uniform_int_distribution<Index> any_face(0, soup.num_faces() - 1);
  const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
  INFO("corruption " << kind);
  if (kind == 0) {
    const Index a = any_vertex(rng), b = any_vertex(rng);
    for (Index& v : soup.face_vertices)
      if (v == b) v = a;
  } else if (kind == 1) {
    soup.add_face({any_vertex(rng), any_vertex(rng), any_vertex(rng)});
  } else {
    const Index f = any_face(rng);
    std::vector<Index> vs(soup.face_vertices.begin() + soup.face_offsets[f],
                          soup.face_vertices.begin() + soup.face_offsets[f + 1]);
    if (kind == 2) {
      soup.add_face(vs);
    } else {
      PolygonSoup rest;
      rest.positions = soup.positions;
      for (Index g = 0; g < soup.num_faces(); ++g)
        if (g != f)
          rest.add_face(std::vector<Index>(soup.face_vertices.begin() + soup.face_offsets[g],
                                           soup.face_vertices.begin() + soup.face_offsets[g + 1]));
      soup = std::move(rest);
    }
  }
  const test::BruteForceTopology brute = test::brute_force_topology(soup);
  INFO(brute.problem);
  if (brute.is_manifold) {
    test::check_same_report(topology_report(build_mesh(soup)), brute.report);
  } else {
    CHECK_THROWS_AS(build_mesh(soup), TopologyError);
  }
}

}  // namespace

// The seeded subset that `make test` runs; `make soak` runs the hidden [soak] cases below.
TEST_CASE("random 2-manifolds: the kernel's report equals a brute-force count", "[kernel]") {
  for (unsigned seed = 1; seed <= 300; ++seed) check_random_manifold(seed);
}

TEST_CASE("random corrupted 2-manifolds: the kernel refuses exactly the non-manifold ones", "[kernel]") {
  for (unsigned seed = 1; seed <= 300; ++seed) check_corrupted_manifold(seed);
}

TEST_CASE("random 2-manifolds of up to 300 polygons: report and refusals equal a brute-force count",
          "[kernel]") {
  const test::RandomManifoldOptions large{.max_polygons = 300};
  for (unsigned seed = 1; seed <= 12; ++seed) {
    check_random_manifold(seed, large);
    check_corrupted_manifold(seed, large);
  }
}

TEST_CASE("soak: 10,000 random 2-manifolds", "[.][soak]") {
  for (unsigned seed = 1; seed <= 10000; ++seed) check_random_manifold(seed);
}

TEST_CASE("soak: 10,000 random corrupted 2-manifolds", "[.][soak]") {
  for (unsigned seed = 1; seed <= 10000; ++seed) check_corrupted_manifold(seed);
}
