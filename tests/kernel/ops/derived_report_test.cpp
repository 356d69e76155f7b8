#include <catch2/catch.hpp>

#include <random>

#include "nome/ops/offset.hpp"
#include "nome/ops/offset_report.hpp"
#include "nome/ops/subdivide.hpp"
#include "nome/ops/subdivided_report.hpp"
#include "support/random_manifold.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

std::vector<PolygonSoup> report_shapes() {
  PolygonSoup with_isolated = test::cube();
  with_isolated.add_vertex({5.0, 5.0, 5.0});
  return {test::torus(6, 4),
          test::mobius_band(9, 2),
          test::mobius_band(10, 1, 2),
          test::klein_bottle(8, 6),
          test::projective_plane(),
          test::grid(3, 2),
          test::disjoint_union(test::tetrahedron(), test::mobius_band(7, 1)),
          with_isolated};
}

void check_same_report(const TopologyReport& derived, const TopologyReport& expected) {
  CHECK(derived.vertices == expected.vertices);
  CHECK(derived.edges == expected.edges);
  CHECK(derived.faces == expected.faces);
  CHECK(derived.chi == expected.chi);
  CHECK(derived.orientable == expected.orientable);
  CHECK(derived.borders == expected.borders);
  CHECK(derived.mobius_edges == expected.mobius_edges);
  CHECK(derived.isolated_vertices == expected.isolated_vertices);
  REQUIRE(derived.components.size() == expected.components.size());
  for (size_t k = 0; k < derived.components.size(); ++k) {
    CAPTURE(k);
    CHECK(derived.components[k].vertices == expected.components[k].vertices);
    CHECK(derived.components[k].edges == expected.components[k].edges);
    CHECK(derived.components[k].faces == expected.components[k].faces);
    CHECK(derived.components[k].chi == expected.components[k].chi);
    CHECK(derived.components[k].orientable == expected.components[k].orientable);
    CHECK(derived.components[k].borders == expected.components[k].borders);
    CHECK(derived.components[k].genus == expected.components[k].genus);
    CHECK(derived.components[k].mobius_edges == expected.components[k].mobius_edges);
  }
}

}  // namespace

TEST_CASE("the report derived over subdivision levels is the subdivided mesh's", "[kernel]") {
  for (const PolygonSoup& soup : report_shapes()) {
    const Mesh mesh = build_mesh(soup);
    for (int levels : {1, 2, 3}) {
      CAPTURE(mesh.num_faces(), levels);
      check_same_report(subdivided_topology_report(mesh, levels), topology_report(subdivide(mesh, {levels})));
    }
  }
}

TEST_CASE("the report derived over the offset is the offset solid's", "[kernel]") {
  for (const PolygonSoup& soup : report_shapes()) {
    const Mesh mesh = build_mesh(soup);
    CAPTURE(mesh.num_faces());
    check_same_report(offset_topology_report(mesh), topology_report(offset(mesh, {0.05})));
  }
  // Random gluings: handles, cross-caps, borders and several parts, faces reversed at random.
  for (unsigned i = 0; i < 200; ++i) {
    const unsigned seed = test::seed_base() + i;
    INFO("seed " << seed << " (NOME_SEED=" << test::seed_base() << ")");
    std::mt19937 rng{seed};
    const Mesh mesh = build_mesh(test::random_manifold(rng).soup);
    check_same_report(offset_topology_report(mesh), topology_report(offset(mesh, {0.05})));
  }
}
