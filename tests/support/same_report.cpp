#include "support/same_report.hpp"

#include <catch2/catch.hpp>

namespace nome::test {

void check_same_report(const TopologyReport& got, const TopologyReport& want) {
  CHECK(got.vertices == want.vertices);
  CHECK(got.edges == want.edges);
  CHECK(got.faces == want.faces);
  CHECK(got.chi == want.chi);
  CHECK(got.orientable == want.orientable);
  CHECK(got.borders == want.borders);
  CHECK(got.mobius_edges == want.mobius_edges);
  CHECK(got.isolated_vertices == want.isolated_vertices);
  REQUIRE(got.components.size() == want.components.size());
  for (size_t i = 0; i < got.components.size(); ++i) {
    const ComponentTopology &g = got.components[i], &w = want.components[i];
    INFO("part " << i);
    CHECK(g.vertices == w.vertices);
    CHECK(g.edges == w.edges);
    CHECK(g.faces == w.faces);
    CHECK(g.chi == w.chi);
    CHECK(g.orientable == w.orientable);
    CHECK(g.borders == w.borders);
    CHECK(g.genus == w.genus);
    CHECK(g.mobius_edges == w.mobius_edges);
  }
}

}  // namespace nome::test
