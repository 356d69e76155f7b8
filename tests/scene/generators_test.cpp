#include <catch2/catch.hpp>

#include <cmath>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/scene/generators.hpp"

using namespace nome;
using namespace nome::scene;

TEST_CASE("funnel: named circles at the report's radii and heights", "[scene]") {
  const Piece p = funnel({8, 0.5, -0.2, 0.3});
  REQUIRE(p.soup.num_vertices() == 16);
  REQUIRE(p.soup.num_faces() == 8);
  CHECK(p.soup.vertex_names[0] == "bc0");
  CHECK(p.soup.vertex_names[15] == "hc7");
  CHECK(p.soup.positions[0].x == Approx(0.5));
  CHECK(p.soup.positions[2].y == Approx(0.5));  // bc2 at 90 degrees
  CHECK(p.soup.positions[8].x == Approx(0.4));  // hc0: radius ro*(1+ratio)
  CHECK(p.soup.positions[8].z == Approx(0.3));
  const TopologyReport r = topology_report(build_mesh(p.soup));
  CHECK(r.chi == 0);
  CHECK(r.borders == 2);
  CHECK(r.orientable);
  CHECK(r.mobius_edges == 0);
}

TEST_CASE("funnel faces point away from the axis", "[scene]") {
  const Piece p = funnel({6, 1, 0, 1});
  const auto& s = p.soup;
  const Vec3 a = s.positions[s.face_vertices[0]], b = s.positions[s.face_vertices[1]],
             c = s.positions[s.face_vertices[2]];
  const Vec3 n = glm::cross(b - a, c - b);
  const Vec3 centre = (a + c) * 0.5;
  CHECK(glm::dot(n, Vec3(centre.x, centre.y, 0)) > 0);
}

TEST_CASE("tunnel: base, high and low circles, one orientable annulus", "[scene]") {
  const Piece p = tunnel({5, 1, 0.5, 2, 0.5, 2});
  REQUIRE(p.soup.num_vertices() == 15);
  CHECK(p.soup.vertex_names[5] == "hc0");
  CHECK(p.soup.vertex_names[10] == "lc0");
  CHECK(p.soup.positions[10].z == Approx(-2));
  CHECK(p.soup.positions[10].x == Approx(1.5));
  const TopologyReport r = topology_report(build_mesh(p.soup));
  CHECK(r.components.size() == 1);
  CHECK(r.chi == 0);
  CHECK(r.borders == 2);
  CHECK(r.orientable);
  CHECK(r.mobius_edges == 0);
}

TEST_CASE("circle is a closed rim line", "[scene]") {
  const Piece p = circle(7, 2);
  CHECK(p.soup.num_vertices() == 7);
  CHECK(p.soup.num_faces() == 0);
  REQUIRE(p.rims.size() == 1);
  CHECK(p.rims[0].is_loop);
  CHECK(p.rims[0].vertices.size() == 7);
  CHECK(glm::length(p.soup.positions[3]) == Approx(2));
}

TEST_CASE("mobius strip: odd twists give one single-sided band", "[scene]") {
  for (int cuts : {1, 3}) {
    const Piece p = mobius_strip({1, 1, cuts, 20});
    const TopologyReport r = topology_report(build_mesh(p.soup));
    CHECK(r.components.size() == 1);
    CHECK(r.chi == 0);
    CHECK(r.borders == 1);
    CHECK_FALSE(r.orientable);
  }
  const TopologyReport two = topology_report(build_mesh(mobius_strip({1, 2, 2, 20}).soup));
  CHECK(two.borders == 2);
  CHECK(two.orientable);
}
