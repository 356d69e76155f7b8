// The rim ribbon (report 6.3): `ribbon NAME (RIMLINE width azimuth twist) endribbon`.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "nome/mesh/topology_report.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// A closed rim line of eight points around a circle of radius 2, and a ribbon along it.
std::string ribbon_scene(const std::string& twist, const std::string& bank = "") {
  std::string text = bank;
  for (int i = 0; i < 8; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 8;
    text += "point q" + std::to_string(i) + " (" + std::to_string(2 * std::cos(a)) + " " +
            std::to_string(2 * std::sin(a)) + " 0) endpoint\n";
  }
  return text +
         "polyline rim (q0 q1 q2 q3 q4 q5 q6 q7) isloop endpolyline\n"
         "ribbon band (rim 0.4 0 " +
         twist + ") endribbon\ninstance b band endinstance\n";
}

TopologyReport ribbon_topology(const Scene& s) {
  return topology_report(build_mesh(s.combined_soup()));
}

}  // namespace

TEST_CASE("a ribbon with half a turn on a closed rim line is a Möbius band", "[scene]") {
  for (const char* twist : {"180", "540", "-180"}) {
    INFO(twist);
    const TopologyReport t = ribbon_topology(Scene::from_text(ribbon_scene(twist), "t.nome"));
    CHECK(t.faces == 8);
    CHECK_FALSE(t.orientable);
    CHECK(t.borders == 1);
    CHECK(t.chi == 0);
  }
}

TEST_CASE("a ribbon with whole turns on a closed rim line is an annulus", "[scene]") {
  for (const char* twist : {"0", "360"}) {
    INFO(twist);
    const TopologyReport t = ribbon_topology(Scene::from_text(ribbon_scene(twist), "t.nome"));
    CHECK(t.faces == 8);
    CHECK(t.orientable);
    CHECK(t.borders == 2);
    CHECK(t.chi == 0);
  }
}

TEST_CASE("a ribbon's width, azimuth and twist follow sliders", "[scene]") {
  const std::string bank =
      "bank rb\n  set w 0.4 0.1 1 0.1\n  set az 0 0 90 5\n  set tw 0 0 720 180\nendbank\n";
  std::string text = ribbon_scene("{$rb_tw}", bank);
  text.replace(text.find("0.4 0 {"), 7, "{$rb_w} {$rb_az} {");
  Scene s = Scene::from_text(text, "t.nome");
  // Flat in the rim line's plane, the band 0.4 across its segments: at a corner (45 degrees of turn) it
  // is mitred, as every sweep is, so 0.4 / cos(22.5 degrees) across the corner.
  const double miter = 1 / std::cos(std::numbers::pi / 8);
  const auto width_at_0 = [&] {
    const PolygonSoup soup = s.combined_soup();
    return glm::length(soup.positions[0] - soup.positions[1]);
  };
  CHECK(width_at_0() == Approx(0.4 * miter));
  s.set_parameter(*s.find_parameter("rb_w"), 0.8);
  CHECK(width_at_0() == Approx(0.8 * miter));
  double highest = 0;
  s.set_parameter(*s.find_parameter("rb_az"), 90);
  for (const Vec3& p : s.combined_soup().positions) highest = std::max(highest, std::abs(p.z));
  CHECK(highest == Approx(0.4));  // standing up: half the width above and below the line
  CHECK(ribbon_topology(s).orientable);
  s.set_parameter(*s.find_parameter("rb_tw"), 180);
  CHECK_FALSE(ribbon_topology(s).orientable);
}

TEST_CASE("a ribbon is saved as written and its rim line must be a curve", "[scene]") {
  const Scene s = Scene::from_text(ribbon_scene("180"), "t.nome");
  const std::string saved = to_nome_text(s);
  CHECK_THAT(saved, Catch::Contains("ribbon band (rim 0.4 0 180) endribbon"));
  CHECK(Scene::from_text(saved, "saved.nome").combined_soup().positions == s.combined_soup().positions);
  CHECK(test::scene_errors(
            "point p (0 0 0) endpoint\nribbon r (p 1 0 0) endribbon\ninstance i r endinstance\n") ==
        std::vector<std::string>{"t.nome:2:11: ribbon 'r': 'p' is no rim line (a polyline, circle, "
                                 "beziercurve or bspline)"});
}

// A rim line through a placed mesh's vertices makes the ribbon wait for that placement, wherever its
// instance is written, and follow it when a slider moves it.
TEST_CASE("a ribbon along the vertices of a placement written after it follows that placement", "[scene]") {
  Scene s = Scene::from_text(
      "bank b\n  set z 2 0 5 0.5\nendbank\n"
      "mesh sq\n"
      "  point a (0 0 0) endpoint  point b (1 0 0) endpoint  point c (1 1 0) endpoint  point d (0 1 0) "
      "endpoint\n"
      "  face f (a b c d) endface\n"
      "endmesh\n"
      "polyline rim (s_a s_b s_c s_d) isloop endpolyline\n"
      "ribbon band (rim 0.2 0 0) endribbon\n"
      "instance r band endinstance\n"
      "instance s sq translate (0 0 {expr $b_z}) endinstance\n",
      "t.nome");
  const auto ribbon_heights = [&] {
    const Piece& band = s.instances()[0].geometry;
    REQUIRE(band.soup.num_faces() == 4);
    double low = 1e9, high = -1e9;
    for (const Vec3& p : band.soup.positions) low = std::min(low, p.z), high = std::max(high, p.z);
    return std::pair{low, high};
  };
  CHECK(ribbon_heights() == std::pair{2.0, 2.0});
  s.set_parameter(*s.find_parameter("b_z"), 3.5);
  CHECK(ribbon_heights() == std::pair{3.5, 3.5});
  CHECK(test::vertex_position(s, "s_c") == Vec3(1, 1, 3.5));
}
