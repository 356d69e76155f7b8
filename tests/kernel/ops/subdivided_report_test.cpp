#include <catch2/catch.hpp>

#include "nome/ops/subdivide.hpp"
#include "nome/ops/subdivided_report.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("the report derived over subdivision levels is the subdivided mesh's", "[kernel]") {
  PolygonSoup with_isolated = test::cube();
  with_isolated.add_vertex({5.0, 5.0, 5.0});
  const PolygonSoup shapes[] = {test::torus(6, 4),
                                test::mobius_band(9, 2),
                                test::mobius_band(10, 1, 2),
                                test::klein_bottle(8, 6),
                                test::projective_plane(),
                                test::grid(3, 2),
                                test::disjoint_union(test::tetrahedron(), test::mobius_band(7, 1)),
                                with_isolated};
  for (const PolygonSoup& soup : shapes) {
    const Mesh mesh = build_mesh(soup);
    for (int levels : {1, 2, 3}) {
      CAPTURE(mesh.num_faces(), levels);
      const TopologyReport expected = topology_report(subdivide(mesh, {levels}));
      const TopologyReport derived = subdivided_topology_report(mesh, levels);
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
        CHECK(derived.components[k].vertices == expected.components[k].vertices);
        CHECK(derived.components[k].edges == expected.components[k].edges);
        CHECK(derived.components[k].faces == expected.components[k].faces);
        CHECK(derived.components[k].genus == expected.components[k].genus);
        CHECK(derived.components[k].mobius_edges == expected.components[k].mobius_edges);
      }
    }
  }
}
