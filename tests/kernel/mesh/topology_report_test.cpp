#include <catch2/catch.hpp>

#include "nome/mesh/topology_report.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {
TopologyReport report_of(const PolygonSoup& s) {
  return topology_report(build_mesh(s));
}
}  // namespace

TEST_CASE("classification table", "[kernel]") {
  struct Row {
    const char* name;
    PolygonSoup soup;
    long long chi;
    bool orientable;
    Index borders;
    long long genus;
  };
  const Row rows[] = {
      {"tetrahedron (sphere)", test::tetrahedron(), 2, true, 0, 0},
      {"cube (sphere)", test::cube(), 2, true, 0, 0},
      {"torus", test::torus(8, 5), 0, true, 0, 1},
      {"open grid (disk)", test::grid(4, 3), 1, true, 1, 0},
      {"Möbius band, one quad wide", test::mobius_band(5, 1), 0, false, 1, 1},
      {"Möbius band, four quads wide", test::mobius_band(16, 4), 0, false, 1, 1},
      {"Klein bottle", test::klein_bottle(10, 6), 0, false, 0, 2},
      {"projective plane", test::projective_plane(), 1, false, 0, 1},
  };
  for (const Row& row : rows) {
    INFO(row.name);
    const TopologyReport r = report_of(row.soup);
    REQUIRE(r.components.size() == 1);
    CHECK(r.chi == row.chi);
    CHECK(r.orientable == row.orientable);
    CHECK(r.borders == row.borders);
    CHECK(r.components[0].genus == row.genus);
    CHECK(r.components[0].chi == row.chi);
  }
}

TEST_CASE("a torus with a random third of its faces reversed is still orientable", "[kernel]") {
  std::mt19937 rng{42};
  const TopologyReport r = report_of(test::reverse_random_faces(test::torus(12, 8), 1.0 / 3.0, rng));
  CHECK(r.orientable);
  CHECK(r.chi == 0);
  CHECK(r.mobius_edges > 0);
  CHECK(r.components[0].genus == 1);
}

TEST_CASE("the report does not change under renumbering, corner rotation and face reversal", "[kernel]") {
  std::mt19937 rng{42};
  const PolygonSoup shapes[] = {test::torus(7, 5), test::mobius_band(9, 3), test::klein_bottle(8, 6),
                                test::projective_plane(), test::grid(3, 5)};
  for (const PolygonSoup& s : shapes) {
    const TopologyReport base = report_of(s);
    for (int trial = 0; trial < 5; ++trial) {
      PolygonSoup t = test::renumber_vertices(s, rng);
      t = test::rotate_corners(t, rng);
      t = test::reverse_random_faces(t, 0.5, rng);
      const TopologyReport r = report_of(t);
      CHECK(r.vertices == base.vertices);
      CHECK(r.edges == base.edges);
      CHECK(r.faces == base.faces);
      CHECK(r.chi == base.chi);
      CHECK(r.orientable == base.orientable);
      CHECK(r.borders == base.borders);
      CHECK(r.components[0].genus == base.components[0].genus);
    }
  }
}

TEST_CASE("components are reported separately and summed", "[kernel]") {
  const TopologyReport r = report_of(test::disjoint_union(test::torus(6, 4), test::mobius_band(6, 1)));
  REQUIRE(r.components.size() == 2);
  CHECK(r.components[0].orientable);
  CHECK_FALSE(r.components[1].orientable);
  CHECK_FALSE(r.orientable);
  CHECK(r.borders == 1);
  CHECK(r.chi == 0);
}

TEST_CASE("vertices in no face are counted apart", "[kernel]") {
  PolygonSoup s = test::tetrahedron();
  s.add_vertex({5, 5, 5});
  const TopologyReport r = report_of(s);
  CHECK(r.isolated_vertices == 1);
  CHECK(r.vertices == 4);
  CHECK(r.chi == 2);
}
