// JIPCAD's (the successor's) dialect by positions: which argument is which in its funnel, tunnel, circle
// and mobiusstrip, how the file's dialect is decided, and what a later definition of the same name does.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "nome/scene/parser.hpp"
#include "nome/scene/scene.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

constexpr double succ_pi = 3.14159265358979323846;

// Vertex k of an n-gon of radius r at height z, 360 k / n degrees from +x.
Vec3 succ_ring_point(int k, int n, double r, double z) {
  return {r * std::cos(2 * succ_pi * k / n), r * std::sin(2 * succ_pi * k / n), z};
}

double succ_gap(const Scene& s, const std::string& name, const Vec3& expected) {
  return glm::length(test::vertex_position(s, name) - expected);
}

bool succ_has_warning(const Scene& s, const std::string& part) {
  for (const Diagnostic& d : s.warnings())
    if (d.message.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("JIPCAD's funnel reads (radius ratio height segs), the report's (n ro ratio h)", "[scene]") {
  // The disk decides the dialect: it is a statement only JIPCAD has.
  const Scene jip = Scene::from_text(
      "disk d (1 360 3) enddisk\nfunnel f (2 0.5 1.25 5) endfunnel\ninstance i f endinstance\n", "t.nom");
  REQUIRE(jip.dialect().dialect == Dialect::jipcad);
  REQUIRE(jip.combined_soup().num_vertices() == 10);
  for (int k = 0; k < 5; ++k) {
    INFO("k = " << k);
    CHECK(succ_gap(jip, "i_v1_" + std::to_string(k), succ_ring_point(k, 5, 2, 0)) < 1e-12);
    CHECK(succ_gap(jip, "i_v2_" + std::to_string(k), succ_ring_point(k, 5, 3, 1.25)) < 1e-12);
  }
  const Scene report =
      Scene::from_text("funnel f (5 2 0.5 1.25) endfunnel\ninstance i f endinstance\n", "t.nome");
  REQUIRE(report.dialect().dialect == Dialect::report2016);
  for (int k = 0; k < 5; ++k) {
    CHECK(succ_gap(report, "i_bc" + std::to_string(k), succ_ring_point(k, 5, 2, 0)) < 1e-12);
    CHECK(succ_gap(report, "i_hc" + std::to_string(k), succ_ring_point(k, 5, 3, 1.25)) < 1e-12);
  }
}

TEST_CASE("JIPCAD's tunnel reads (radius ratio height segs): outer circles at +-height", "[scene]") {
  const Scene s = Scene::from_text("tunnel t (1.5 -0.2 0.75 6) endtunnel\ninstance i t endinstance\n",
                                   "t.nom", {.dialect = Dialect::jipcad});
  REQUIRE(s.combined_soup().num_vertices() == 18);
  for (int k = 0; k < 6; ++k) {
    INFO("k = " << k);
    CHECK(succ_gap(s, "i_bc" + std::to_string(k), succ_ring_point(k, 6, 1.5, 0)) < 1e-12);
    CHECK(succ_gap(s, "i_hc" + std::to_string(k), succ_ring_point(k, 6, 1.2, 0.75)) < 1e-12);
    CHECK(succ_gap(s, "i_lc" + std::to_string(k), succ_ring_point(k, 6, 1.2, -0.75)) < 1e-12);
  }
  // JIPCAD's tunnel has no lower-half arguments.
  CHECK_THROWS_AS(Scene::from_text("tunnel t (1 0.5 2 6 0.1 1) endtunnel\ninstance i t endinstance\n",
                                   "t.nom", {.dialect = Dialect::jipcad}),
                  SceneError);
}

TEST_CASE("the file's dialect decides the order: its header line, or the --dialect option", "[scene]") {
  const std::string funnel = "funnel f (3 0.5 2 4) endfunnel\ninstance i f endinstance\n";
  const Scene headed = Scene::from_text(std::string(jipcad_header) + "\n" + funnel, "t.nom");
  CHECK(headed.dialect().dialect == Dialect::jipcad);
  CHECK(succ_gap(headed, "i_v2_1", succ_ring_point(1, 4, 4.5, 2)) < 1e-12);
  // Read the report's way the same numbers are 3 segments of radius 0.5.
  const Scene report = Scene::from_text(funnel, "t.nome");
  CHECK(report.combined_soup().num_vertices() == 6);
  CHECK(succ_gap(report, "i_hc1", succ_ring_point(1, 3, 0.5 * 3, 4)) < 1e-12);
  // The option wins over the text's own cue.
  const Scene forced =
      Scene::from_text("disk d (1 360 3) enddisk\n" + funnel, "t.nom", {.dialect = Dialect::report2016});
  CHECK(forced.dialect().dialect == Dialect::report2016);
  CHECK(succ_gap(forced, "i_hc2", succ_ring_point(2, 3, 1.5, 4)) < 1e-12);
}

TEST_CASE("JIPCAD's circle reads (radius segs)", "[scene]") {
  const Scene s = Scene::from_text("circle c (2.5 7) endcircle\ninstance i c endinstance\n", "t.nom",
                                   {.dialect = Dialect::jipcad});
  REQUIRE(s.combined_soup().num_vertices() == 7);
  for (int k = 0; k < 7; ++k)
    CHECK(succ_gap(s, "i_c" + std::to_string(k), succ_ring_point(k, 7, 2.5, 0)) < 1e-12);
}

TEST_CASE("JIPCAD's mobiusstrip with cuts: equal bands and gaps across its width", "[scene]") {
  // Width 1.5 in 2 cuts: 5 equal strips across (band, gap, band, gap, band) around the unit circle.
  const Scene s = Scene::from_text("mobiusstrip m (1.5 1 2 8) endmobiusstrip\ninstance i m endinstance\n",
                                   "t.nom", {.dialect = Dialect::jipcad});
  const PolygonSoup soup = s.combined_soup();
  REQUIRE(soup.num_vertices() == 8 * 6);
  for (int i = 0; i < 8; ++i) {
    const double around = 2 * succ_pi * i / 8, turn = succ_pi * i / 8;
    const Vec3 radial(std::cos(around), std::sin(around), 0);
    const Vec3 across = std::cos(turn) * radial + Vec3(0, 0, std::sin(turn));
    for (int j = 0; j <= 5; ++j) {
      INFO("v" << i << "_" << j);
      CHECK(succ_gap(s, "i_v" + std::to_string(i) + "_" + std::to_string(j),
                     radial + 1.5 * (j / 5.0 - 0.5) * across) < 1e-12);
    }
  }
  CHECK(soup.num_faces() == 8 * 3);
}

TEST_CASE("in JIPCAD's dialect a later definition of a name replaces the earlier one everywhere", "[scene]") {
  const Scene s = Scene::from_text(
      "disk d (1 360 4) enddisk\ninstance before d endinstance\n"
      "funnel d (2 0 1 4) endfunnel\ninstance after d endinstance\n",
      "t.nom", {.dialect = Dialect::jipcad});
  REQUIRE(s.instances().size() == 2);
  for (const char* placement : {"before", "after"}) {
    INFO(placement);
    const std::string p(placement);
    CHECK(succ_gap(s, p + "_v1_0", {2, 0, 0}) < 1e-12);
    CHECK(succ_gap(s, p + "_v2_1", {0, 2, 1}) < 1e-12);
  }
  CHECK(s.combined_soup().num_faces() == 8);
  CHECK(succ_has_warning(s, "'d' is defined again (first at "));
  // Points too: the face takes the later position.
  const Scene pts = Scene::from_text(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
      "point a (0 0 5) endpoint\nface f (a b c) endface\ninstance i f endinstance\n",
      "t.nom", {.dialect = Dialect::jipcad});
  CHECK(succ_gap(pts, "i_a", {0, 0, 5}) < 1e-12);
  // Three definitions: the last one.
  const Scene three = Scene::from_text(
      "disk d (1 360 4) enddisk\ndisk d (2 360 4) enddisk\ndisk d (3 360 4) enddisk\ninstance i d "
      "endinstance\n",
      "t.nom");
  CHECK(succ_gap(three, "i_v0_0", {3, 0, 0}) < 1e-12);
}

TEST_CASE("in the report's dialect a second definition of a name is an error at it", "[scene]") {
  const std::vector<std::string> errors = test::scene_errors(
      "funnel f (4 1 0 1) endfunnel\nfunnel f (4 2 0 1) endfunnel\ninstance i f endinstance\n");
  REQUIRE(errors.size() == 1);
  CHECK_THAT(errors[0], Catch::StartsWith("t.nome:2:8: duplicate name 'f' (first defined at "));
}
