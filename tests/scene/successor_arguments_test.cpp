// JIPCAD's (the successor's) dialect by positions: which argument is which in its funnel, tunnel, circle
// and mobiusstrip, how the file's dialect is decided, and what a later definition of the same name does.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

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

TEST_CASE("succ: in JIPCAD's dialect (3 20) is radius 3 in 20 segments, whatever the values", "[scene]") {
  // Both numbers could count segments: the dialect decides, as intro_files__Generators.nom means it.
  const std::string text = "circle c (3 20) endcircle\ninstance i c endinstance\n";
  const Scene jip = Scene::from_text(text, "t.nom", {.dialect = Dialect::jipcad});
  REQUIRE(jip.combined_soup().num_vertices() == 20);
  for (int k = 0; k < 20; ++k) {
    INFO("k = " << k);
    CHECK(succ_gap(jip, "i_c" + std::to_string(k), succ_ring_point(k, 20, 3, 0)) < 1e-12);
  }
  CHECK(jip.warnings().empty());
  // The 2016 dialect keeps NOME 2.x's (n r): 3 segments of radius 20.
  const Scene report = Scene::from_text(text, "t.nome");
  REQUIRE(report.dialect().dialect == Dialect::report2016);
  REQUIRE(report.combined_soup().num_vertices() == 3);
  for (int k = 0; k < 3; ++k)
    CHECK(succ_gap(report, "i_c" + std::to_string(k), succ_ring_point(k, 3, 20, 0)) < 1e-12);
  // One segment is no circle: a statement only NOME 2.x's order can mean is read so, and the warning says so.
  const Scene old = Scene::from_text("circle c (20 1) endcircle\ninstance i c endinstance\n", "t.nom",
                                     {.dialect = Dialect::jipcad});
  REQUIRE(old.combined_soup().num_vertices() == 20);
  CHECK(succ_gap(old, "i_c5", succ_ring_point(5, 20, 1, 0)) < 1e-12);
  REQUIRE(old.warnings().size() == 1);
  CHECK(old.warnings()[0].location.column == 11);
  CHECK_THAT(old.warnings()[0].message,
             Catch::Contains("reads (radius segs)") && Catch::Contains("20 segments of radius 1"));
}

// (segs a b c sheet theta) as JIPCAD's Hyperboloid.cpp reads them: column i of segs at t = i theta pi / segs,
// rows at the whole heights z, radius factor sqrt(z^2 + 1) (one sheet) or sqrt(z^2 - 1) (two sheets).
Vec3 succ_hyperboloid_point(double a, double b, double theta, int segs, int i, int z, double sign) {
  const double t = i * theta * succ_pi / segs, s = std::sqrt(double(z) * z + sign);
  return {a * s * std::cos(t), b * s * std::sin(t), double(z)};
}

TEST_CASE("succ: JIPCAD's hyperboloid reads (segs a b c sheet theta), by its closed form", "[scene]") {
  // One sheet, a whole turn: 7 around, x scale 1.5, y scale 0.5, rows z = -2..2.
  const Scene one =
      Scene::from_text("hyperboloid h (7 1.5 0.5 2 0 2) endhyperboloid\ninstance i h endinstance\n", "t.nom",
                       {.dialect = Dialect::jipcad});
  REQUIRE(one.combined_soup().num_vertices() == 7 * 5);
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i < 7; ++i) {
      INFO("v" << i << "_" << j);
      CHECK(succ_gap(one, "i_v" + std::to_string(i) + "_" + std::to_string(j),
                     succ_hyperboloid_point(1.5, 0.5, 2, 7, i, j - 2, 1)) < 1e-12);
    }
  CHECK(one.combined_soup().num_faces() == 7 * 4);
  // Two sheets, half a turn: 40 columns at 0, 1/40 pi, ..., 39/40 pi (JIPCAD's sampling stops
  // a step short of theta pi); each sheet from its apex at z = +-1 to +-3.
  const Scene two =
      Scene::from_text("hyperboloid h (40 1 1 3 1 1) endhyperboloid\ninstance i h endinstance\n", "t.nom",
                       {.dialect = Dialect::jipcad});
  REQUIRE(two.combined_soup().num_vertices() == 2 * (1 + 2 * 40));
  CHECK(succ_gap(two, "i_top_apex", {0, 0, 1}) < 1e-12);
  CHECK(succ_gap(two, "i_bottom_apex", {0, 0, -1}) < 1e-12);
  for (int i = 0; i < 40; ++i) {
    INFO("column " << i);
    CHECK(succ_gap(two, "i_top_v" + std::to_string(i) + "_2", succ_hyperboloid_point(1, 1, 1, 40, i, 3, -1)) <
          1e-12);
    CHECK(succ_gap(two, "i_bottom_v" + std::to_string(i) + "_0",
                   succ_hyperboloid_point(1, 1, 1, 40, i, -3, -1)) < 1e-12);
    CHECK(succ_gap(two, "i_bottom_v" + std::to_string(i) + "_1",
                   succ_hyperboloid_point(1, 1, 1, 40, i, -2, -1)) < 1e-12);
  }
  // `(40 1 1 3 0 2)`, refused before, is a whole one-sheeted turn.
  const Scene whole =
      Scene::from_text("hyperboloid h (40 1 1 3 0 2) endhyperboloid\ninstance i h endinstance\n", "t.nom",
                       {.dialect = Dialect::jipcad});
  CHECK(succ_gap(whole, "i_v10_6", succ_hyperboloid_point(1, 1, 2, 40, 10, 3, 1)) < 1e-12);
}

// JIPCAD's language reference documents the hyperboloid with the sliders A C UMax UIncrement VIncrement
// Sheet: NOME3's older order, which JIPCAD's own Hyperboloid.cpp no longer reads.
std::string documented_hyperboloid(int sheet) {
  return "bank hyp\n"
         "  set A 1 0.1 5 0.1\n"
         "  set C 1.1 0.1 5 0.1\n"
         "  set UMax 1.2 0.1 3 0.1\n"
         "  set UIncrement 6 1 50 1\n"
         "  set VIncrement 12 3 50 1\n"
         "  set Sheet " +
         std::to_string(sheet) +
         " 0 2 1\n"
         "endbank\n"
         "hyperboloid h ({expr $hyp.A} {expr $hyp.C} {expr $hyp.UMax} {expr $hyp.UIncrement} "
         "{expr $hyp.VIncrement} {expr $hyp.Sheet}) endhyperboloid\n"
         "instance i h endinstance\n";
}

TEST_CASE("succ: the hyperboloids of JIPCAD's reference, in NOME3's older order, open with a warning",
          "[scene]") {
  const double a = 1, c = 1.1, u_max = 1.2;
  const int u_segs = 6, v_segs = 12;
  const auto around = [&](int i) { return 2 * succ_pi * i / v_segs; };
  // One sheet: (a cosh u cos t, a cosh u sin t, c sinh u), u from -u_max to u_max.
  const Scene one = Scene::from_text(documented_hyperboloid(0), "doc.nom", {.dialect = Dialect::jipcad});
  REQUIRE(one.warnings().size() == 1);
  CHECK(one.warnings()[0].location.line == 9);
  CHECK_THAT(one.warnings()[0].message,
             Catch::Contains("segs must be a whole number in [3, 100000], found 1") &&
                 Catch::Contains("read as NOME3's older (a c u_max u_segs v_segs sheet)"));
  REQUIRE(one.combined_soup().num_vertices() == v_segs * (u_segs + 1));
  CHECK(one.combined_soup().num_faces() == v_segs * u_segs);
  for (int j = 0; j <= u_segs; ++j)
    for (int i = 0; i < v_segs; ++i) {
      INFO("v" << i << "_" << j);
      const double u = -u_max + 2 * u_max * j / u_segs;
      const Vec3 expected(a * std::cosh(u) * std::cos(around(i)), a * std::cosh(u) * std::sin(around(i)),
                          c * std::sinh(u));
      CHECK(succ_gap(one, "i_v" + std::to_string(i) + "_" + std::to_string(j), expected) < 1e-12);
    }
  // Two sheets: (a sinh u cos t, a sinh u sin t, +-c cosh u), u from 0 to u_max, each from its apex.
  const Scene two = Scene::from_text(documented_hyperboloid(2), "doc.nom", {.dialect = Dialect::jipcad});
  REQUIRE(two.warnings().size() == 1);
  REQUIRE(two.combined_soup().num_vertices() == 2 * (1 + v_segs * u_segs));
  CHECK(succ_gap(two, "i_top_apex", {0, 0, c}) < 1e-12);
  CHECK(succ_gap(two, "i_bottom_apex", {0, 0, -c}) < 1e-12);
  for (int j = 1; j <= u_segs; ++j)
    for (int i = 0; i < v_segs; ++i) {
      const double u = u_max * j / u_segs;
      const std::string at = "v" + std::to_string(i) + "_" + std::to_string(j);
      INFO(at);
      CHECK(succ_gap(two, "i_top_" + at,
                     {a * std::sinh(u) * std::cos(around(i)), a * std::sinh(u) * std::sin(around(i)),
                      c * std::cosh(u)}) < 1e-12);
      CHECK(succ_gap(two, "i_bottom_" + at,
                     {a * std::sinh(u) * std::cos(around(i)), a * std::sinh(u) * std::sin(around(i)),
                      -c * std::cosh(u)}) < 1e-12);
    }
  // A slider that keeps the older order keeps the shape in it; arguments neither order reads: only what
  // is wrong, at its place.
  Scene moved = Scene::from_text(documented_hyperboloid(0), "doc.nom", {.dialect = Dialect::jipcad});
  const std::optional<ParameterId> slider = moved.find_parameter("hyp.C");
  REQUIRE(slider);
  moved.set_parameter(*slider, 2.0);
  CHECK(succ_gap(moved, "i_v0_" + std::to_string(u_segs), {a * std::cosh(u_max), 0, 2.0 * std::sinh(u_max)}) <
        1e-12);
  // The same warning at the same place is told once: a second instance, a slider that evaluates it again.
  Scene twice = Scene::from_text(documented_hyperboloid(0) + "instance j h translate (3 0 0) endinstance\n",
                                 "doc.nom", {.dialect = Dialect::jipcad});
  CHECK(twice.warnings().size() == 1);
  twice.set_parameter(*twice.find_parameter("hyp.C"), 1.5);
  CHECK(twice.warnings().size() == 1);
  // A warning that quotes a slider's value follows the slider, there and back.
  Scene quoting = Scene::from_text(documented_hyperboloid(0), "doc.nom", {.dialect = Dialect::jipcad});
  const ParameterId a_slider = *quoting.find_parameter("hyp.A");
  for (const double value : {1.5, 1.0, 1.5}) {
    quoting.set_parameter(a_slider, value);
    const std::vector<Diagnostic> warnings = quoting.warnings();
    REQUIRE(warnings.size() == 1);
    CHECK_THAT(warnings[0].message, Catch::Contains(value == 1.0 ? "found 1: read" : "found 1.5: read"));
  }
  const std::vector<std::string> neither =
      test::scene_errors("hyperboloid h (1 1 1 6 2 0) endhyperboloid\ninstance i h endinstance\n");
  REQUIRE(neither.size() == 1);
  CHECK(neither[0] == "t.nome:1:16: segs must be a whole number in [3, 100000], found 1");
}

TEST_CASE("succ: a face that names its first vertex again at its end is the closed polygon, noted once",
          "[scene]") {
  // As the bell tutorial writes its faces, 32 times: two such faces here, in a mesh and at the top level.
  const std::string points =
      "point sq1 (0 0 0) endpoint point sq2 (1 0 0) endpoint point sq3 (1 1 0) endpoint point sq4 (0 1 0) "
      "endpoint point top (0.5 0.5 1) endpoint\n";
  const std::string text =
      points +
      "mesh m face f (sq1 sq2 sq3 sq4 sq1) endface face g (sq1 top sq2 sq1) endface endmesh\n"
      "face h (sq2 top sq3 sq2) endface\ninstance i m endinstance\ninstance j h endinstance\n";
  const Scene s = Scene::from_text(text, "t.nom", {.dialect = Dialect::jipcad});
  const PolygonSoup soup = s.combined_soup();
  REQUIRE(soup.num_faces() == 3);
  auto corners = [&](Index face) {
    std::vector<Vec3> out;
    for (Index c = soup.face_offsets[face]; c < soup.face_offsets[face + 1]; ++c)
      out.push_back(soup.positions[soup.face_vertices[c]]);
    return out;
  };
  CHECK(corners(0) == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  CHECK(corners(1) == std::vector<Vec3>{{0, 0, 0}, {0.5, 0.5, 1}, {1, 0, 0}});
  CHECK(corners(2) == std::vector<Vec3>{{1, 0, 0}, {0.5, 0.5, 1}, {1, 1, 0}});
  int notes = 0;
  for (const Diagnostic& d : s.warnings()) {
    INFO(d.message);
    CHECK_THAT(d.message, !Catch::Contains("coinciding"));
    if (d.message.find("names its first vertex again") != std::string::npos) ++notes;
  }
  CHECK(notes == 1);
  // The 2016 dialect reads the face as written, its five corners.
  const Scene report =
      Scene::from_text(points + "face f (sq1 sq2 sq3 sq4 sq1) endface\ninstance i f endinstance\n", "t.nome",
                       {.dialect = Dialect::report2016});
  CHECK(report.combined_soup().face_offsets[1] == 5);
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
