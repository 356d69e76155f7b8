// The sweep core (nome/scene/sweep.hpp) and the sweep statements: topology of capped, twisted and
// closed sweeps, the join by position, and the curves they sweep along.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/subdivide.hpp"
#include "nome/scene/save_nome.hpp"
#include "nome/scene/sweep.hpp"
#include "scene/scene_support.hpp"
#include "support/point_sets.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

TopologyReport topology(const PolygonSoup& soup) {
  return topology_report(build_mesh(soup));
}

TopologyReport scene_topology(const std::string& text) {
  return topology(Scene::from_text(text, "t.nome").combined_soup());
}

// `turns` times around a circle of radius 3 in z = 0, n samples a turn.
std::vector<PathSample> circle_path(int n, int turns = 1) {
  std::vector<PathSample> path;
  for (int i = 0; i < n * turns; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    path.push_back({Vec3(3 * std::cos(a), 3 * std::sin(a), 0.0)});
  }
  return path;
}

const CrossSection segment{{{-0.5, 0}, {0.5, 0}}, false};
const CrossSection square_section{{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}, true};

constexpr const char* square_points =
    "point s1 (0.5 0.5 0) endpoint\npoint s2 (-0.5 0.5 0) endpoint\n"
    "point s3 (-0.5 -0.5 0) endpoint\npoint s4 (0.5 -0.5 0) endpoint\n"
    "polyline sq (s1 s2 s3 s4) isloop endpolyline\n";

}  // namespace

TEST_CASE("a capped sweep of a closed cross-section along an open path is closed with chi 2", "[scene]") {
  const std::string text = std::string(square_points) +
                           "point a (0 0 0) endpoint\npoint b (0 0 3) endpoint\npoint c (2 0 5) endpoint\n"
                           "point d (4 1 5) endpoint\npolyline p (a b c d) endpolyline\n"
                           "sweep s crosssection sq begincap endcap endcrosssection path p endpath endsweep\n"
                           "instance i s endinstance\n";
  const TopologyReport r = scene_topology(text);
  CHECK(r.faces == 3 * 4 + 2);
  CHECK(r.borders == 0);
  CHECK(r.chi == 2);
  CHECK(r.orientable);
  CHECK(r.mobius_edges == 0);
  CHECK(r.components.size() == 1);
}

TEST_CASE("a segment swept around a closed path with 180 degrees of twist is a Möbius band", "[scene]") {
  const std::string text =
      "circle ring (5 24) endcircle\npoint a (-1 0 0) endpoint\npoint b (1 0 0) endpoint\n"
      "polyline seg (a b) endpolyline\n"
      "sweep band crosssection seg endcrosssection path ring mintorsion twist (180) endpath endsweep\n"
      "instance i band endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  CHECK(s.warnings().empty());
  const TopologyReport r = topology(s.combined_soup());
  CHECK(r.vertices == 48);
  CHECK(r.faces == 24);
  CHECK(r.borders == 1);
  CHECK(r.chi == 0);
  CHECK_FALSE(r.orientable);
  CHECK(r.mobius_edges > 0);
  CHECK(r.components.size() == 1);
}

TEST_CASE("a closed square swept around a closed path with 90 degrees of twist is a closed torus",
          "[scene]") {
  for (const char* frames : {"mintorsion", ""}) {
    INFO("frames: " << frames);
    const std::string text = std::string(square_points) +
                             "circle ring (16 4) endcircle\n"
                             "sweep t crosssection sq endcrosssection path ring " +
                             frames + " twist (90) endpath endsweep\ninstance i t endinstance\n";
    const TopologyReport r = scene_topology(text);
    CHECK(r.vertices == 64);
    CHECK(r.borders == 0);
    CHECK(r.chi == 0);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
  }
}

TEST_CASE("a twist that no symmetry of the cross-section matches joins by the nearest match, with a warning",
          "[scene]") {
  const std::string text = std::string(square_points) +
                           "circle ring (16 4) endcircle\n"
                           "sweep t crosssection sq endcrosssection path ring twist (50) endpath endsweep\n"
                           "instance i t endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  REQUIRE(s.warnings().size() == 1);
  CHECK_THAT(s.warnings()[0].to_string(), Catch::StartsWith("t.nome:7:7: "));
  CHECK_THAT(s.warnings()[0].to_string(), Catch::Contains("nearest match"));
  const TopologyReport r = topology(s.combined_soup());
  CHECK(r.borders == 0);
  CHECK(r.chi == 0);
  CHECK(r.orientable);  // 50 degrees is nearest to a quarter turn: a torus
}

TEST_CASE("Catmull-Clark on a swept Möbius band equals Catmull-Clark on its orientation double cover",
          "[scene]") {
  for (FrameKind frames : {FrameKind::minimal_torsion, FrameKind::frenet}) {
    SweepOptions o;
    o.frames = frames;
    o.is_path_closed = true;
    o.twist = 180;
    const PolygonSoup band = sweep(circle_path(9), {&segment, 1}, o).piece.soup;
    // Twice around with twice the twist: each point of the band twice, an annulus.
    o.twist = 360;
    const PolygonSoup cover = sweep(circle_path(9, 2), {&segment, 1}, o).piece.soup;
    REQUIRE_FALSE(topology(band).orientable);
    REQUIRE(topology(cover).orientable);
    REQUIRE(topology(cover).borders == 2);
    for (int levels = 1; levels <= 3; ++levels) {
      INFO(levels << " levels");
      const auto subdivided = [&](const PolygonSoup& s) {
        return subdivide(build_mesh(s), {levels, SubdivisionRule::classic}).positions();
      };
      CHECK(test::compare_point_sets(subdivided(band), subdivided(cover), 1e-9, 2) == "");
    }
  }
}

TEST_CASE("sweep core: caps face away from the path, triangles on request, cut ends", "[scene]") {
  std::vector<PathSample> path = {{Vec3(0, 0, 0)}, {Vec3(0, 0, 1)}, {Vec3(0, 0, 2)}, {Vec3(0, 0, 3)}};
  SweepOptions o;
  o.has_begin_cap = o.has_end_cap = true;
  const Piece quads = sweep(path, {&square_section, 1}, o).piece;
  REQUIRE(quads.soup.face_names.back() == "endcap");
  const auto normal = [&](const PolygonSoup& s, Index f) {
    const Vec3 a = s.positions[s.face_vertices[s.face_offsets[f]]];
    const Vec3 b = s.positions[s.face_vertices[s.face_offsets[f] + 1]];
    const Vec3 c = s.positions[s.face_vertices[s.face_offsets[f] + 2]];
    return glm::cross(b - a, c - b);
  };
  CHECK(normal(quads.soup, quads.soup.num_faces() - 1).z > 0);
  CHECK(normal(quads.soup, quads.soup.num_faces() - 2).z < 0);
  CHECK(glm::dot(normal(quads.soup, 0), quads.soup.positions[quads.soup.face_vertices[0]] - Vec3(0, 0, 0)) >
        0);
  CHECK(quads.soup.vertex_names[5] == "v1_1");
  o.faces = FaceShape::triangles;
  o.is_cut_begin = o.is_cut_end = true;
  const Piece triangles = sweep(path, {&square_section, 1}, o).piece;
  CHECK(triangles.soup.num_vertices() == 8);
  CHECK(triangles.soup.num_faces() == 2 * 4 + 2);
  CHECK(topology(triangles.soup).chi == 2);
}

TEST_CASE("rotation-minimising frames do not turn about a helix's tangent, Frenet frames do", "[scene]") {
  std::vector<Vec3> helix;
  for (int i = 0; i <= 200; ++i) {
    const double a = 0.05 * i;
    helix.emplace_back(std::cos(a), std::sin(a), 0.3 * a);
  }
  const std::vector<Frame> rmf = path_frames(helix, false, FrameKind::minimal_torsion);
  double worst = 0;
  for (std::size_t i = 1; i + 1 < rmf.size(); ++i) {
    // The normal's change has no component along the binormal: no turning about the tangent.
    const Vec3 change = rmf[i + 1].normal - rmf[i].normal;
    worst = std::max(worst, std::abs(glm::dot(change, rmf[i].binormal)));
  }
  CHECK(worst < 1e-3);
  const std::vector<Frame> frenet = path_frames(helix, false, FrameKind::frenet);
  CHECK(std::abs(glm::dot(frenet[100].normal, glm::normalize(Vec3(-helix[100].x, -helix[100].y, 0)))) ==
        Approx(1).epsilon(1e-3));
}

TEST_CASE("curves: a B-spline that repeats its first points is closed, a Bézier passes its end points",
          "[scene]") {
  const std::string points =
      std::string(square_points) +
      "point q0 (4 0 0) endpoint\npoint q1 (0 4 0) endpoint\npoint q2 (-4 0 0) endpoint\n"
      "point q3 (0 -4 1) endpoint\n";
  const TopologyReport loop = scene_topology(points +
                                             "bspline b order 3 (q0 q1 q2 q3 q0 q1) segs 40 endbspline\n"
                                             "sweep t crosssection sq endcrosssection path b mintorsion "
                                             "endpath endsweep\ninstance i t endinstance\n");
  CHECK(loop.vertices == 40 * 4);
  CHECK(loop.borders == 0);
  CHECK(loop.chi == 0);
  CHECK(loop.orientable);
  const TopologyReport closed_keyword =
      scene_topology(points +
                     "bspline b order 4 (q0 q1 q2 q3) segs 40 closed endbspline\n"
                     "sweep t crosssection sq endcrosssection path b mintorsion endpath endsweep\ninstance i "
                     "t endinstance\n");
  CHECK(closed_keyword.borders == 0);
  CHECK(closed_keyword.chi == 0);
  const Scene bezier = Scene::from_text(points +
                                            "beziercurve z (q0 q1 q2) segs 10 endbeziercurve\n"
                                            "instance i z endinstance\n",
                                        "t.nome");
  const Piece& rim = bezier.instances()[0].geometry;
  REQUIRE(rim.soup.num_vertices() == 11);
  REQUIRE(rim.rims.size() == 1);
  CHECK_FALSE(rim.rims[0].is_loop);
  CHECK(rim.soup.positions[0] == Vec3(4, 0, 0));
  CHECK(rim.soup.positions[10] == Vec3(-4, 0, 0));
  CHECK(rim.soup.positions[5] == Vec3(0, 2, 0));
}

TEST_CASE("a sweep follows its points' sliders, control points scale and turn its cross-section", "[scene]") {
  const std::string text =
      "bank b set h 3 1 10 0.5 set w 2 0.5 4 0.1 endbank\n" + std::string(square_points) +
      "point a (0 0 0) endpoint\npoint m (0 0 {expr $b_h / 2}) endpoint\npoint c (0 0 {expr $b_h}) endpoint\n"
      "controlpoint cm point m scale ({expr $b_w} {expr $b_w} 0) rotate (0 0 45) endcontrolpoint\n"
      "polyline p (a cm c) endpolyline\n"
      "sweep s crosssection sq endcrosssection path p endpath endsweep\ninstance i s endinstance\n";
  Scene s = Scene::from_text(text, "t.nome");
  CHECK(test::vertex_position(s, "i_v2_0").z == Approx(3));
  // The middle section: twice as large and turned by 45 degrees, so its first point lies on an axis.
  const Vec3 middle = test::vertex_position(s, "i_v1_0");
  CHECK(glm::length(Vec3(middle.x, middle.y, 0)) == Approx(2 * std::sqrt(0.5)));
  CHECK(std::min(std::abs(middle.x), std::abs(middle.y)) == Approx(0).margin(1e-12));
  const ParameterId h = *s.find_parameter("b_h");
  CHECK(s.set_parameter(h, 5).size() == 1);
  CHECK(test::vertex_position(s, "i_v2_0").z == Approx(5));
  CHECK(test::vertex_position(s, "i_v1_0").z == Approx(2.5));
}

TEST_CASE("a slider that moves a sweep's path moves its vertices only; one that changes its join remakes it",
          "[scene]") {
  const auto text = [](double lift, double twist) {
    return "bank b set lift " + std::to_string(lift) + " -1 1 0.1 set tw " + std::to_string(twist) +
           " 0 360 1 endbank\n" + std::string(square_points) +
           "point k0 (3 0 {expr $b_lift}) endpoint\npoint k1 (0 3 0) endpoint\npoint k2 (-3 0 0) endpoint\n"
           "point k3 (0 -3 0) endpoint\nbspline pa order 3 (k0 k1 k2 k3 k0 k1) segs 40 endbspline\n"
           "sweep s crosssection sq endcrosssection path pa mintorsion twist ({expr $b_tw}) endpath "
           "endsweep\n"
           "instance i s translate (1 2 3) endinstance\n";
  };
  Scene s = Scene::from_text(text(0, 90), "t.nome");
  const auto topology_before = s.instances()[0].topology_version;
  const size_t evaluations = s.placement_evaluations();
  s.set_parameter(*s.find_parameter("b_lift"), 0.5);
  CHECK(s.vertex_moves() == 1);
  CHECK(s.placement_evaluations() == evaluations);
  CHECK(s.instances()[0].topology_version == topology_before);
  const PolygonSoup moved = s.combined_soup();
  const PolygonSoup fresh = Scene::from_text(text(0.5, 90), "t.nome").combined_soup();
  CHECK(moved.positions == fresh.positions);
  CHECK(moved.face_vertices == fresh.face_vertices);
  CHECK(moved.vertex_names == fresh.vertex_names);
  CHECK(s.combined_positions() == fresh.positions);

  // 90 degrees more of twist joins the square's points one place further round: new faces.
  s.set_parameter(*s.find_parameter("b_tw"), 180);
  CHECK(s.placement_evaluations() == evaluations + 1);
  CHECK(s.instances()[0].topology_version != topology_before);
  const PolygonSoup remade = Scene::from_text(text(0.5, 180), "t.nome").combined_soup();
  CHECK(s.combined_soup().face_vertices == remade.face_vertices);
  CHECK(s.combined_soup().positions == remade.positions);
}

TEST_CASE("sweepmorph blends the control points' cross-sections, morphvisualizer shows one", "[scene]") {
  const std::string text = std::string(square_points) +
                           "point t1 (1 0 0) endpoint\npoint t2 (0 1 0) endpoint\npoint t3 (-1 0 0) "
                           "endpoint\npoint t4 (0 -1 0) endpoint\n"
                           "polyline dia (t1 t2 t3 t4 t1) endpolyline\n"
                           "point a (0 0 0) endpoint\npoint b (0 0 1) endpoint\npoint c (0 0 2) endpoint\n"
                           "controlpoint ca point a crosssection sq endcontrolpoint\n"
                           "controlpoint cc point c crosssection dia endcontrolpoint\n"
                           "polyline p (ca b cc) endpolyline\n"
                           "sweepmorph m begincap endcap path p endpath endsweepmorph\n"
                           "morphvisualizer mv sweep m index (1) endmorphvisualizer\n"
                           "instance i m endinstance\ninstance j mv endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const TopologyReport r = topology(s.instances()[0].geometry.soup);
  CHECK(r.borders == 0);
  CHECK(r.chi == 2);
  // Half way: the mean of (0.5, 0.5) and (1, 0).
  const Vec3 half = test::vertex_position(s, "j_c0");
  CHECK(half.x == Approx(0.75));
  CHECK(half.y == Approx(0.25));
  CHECK(s.instances()[1].geometry.rims.at(0).is_loop);
}

TEST_CASE("a sweep names what is wrong with its curves", "[scene]") {
  CHECK(test::scene_errors(std::string(square_points) +
                           "sweep s crosssection sq endcrosssection path nowhere endpath endsweep\n"
                           "instance i s endinstance\n") ==
        std::vector<std::string>{"t.nome:6:46: 'nowhere' is no curve: a sweep's path and cross-section are a "
                                 "polyline, circle, beziercurve or bspline"});
  CHECK(test::scene_errors(std::string(square_points) +
                           "sweep s crosssection sq endcrosssection path sq twist endpath endsweep\n") ==
        std::vector<std::string>{"t.nome:6:55: expected a number or '{expr ...}', found 'endpath'"});
}

// The statements of JIPCAD's sweeps__sweeps_circle.nom in the 2016 spelling (the file itself needs the
// successor's `list` and `$b.name`): a rectangle swept around a circle, closed by position.
TEST_CASE("JIPCAD's circle sweep: a rectangle around a circle is a closed orientable torus", "[scene]") {
  const std::string text =
      "bank b\n set s_twist 0 0 360 1\n set s_azimuth 0 0 360 1\nendbank\n"
      "circle myc (5 10) endcircle\n"
      "point point1 (2 1 0) endpoint\npoint point2 (-2 1 0) endpoint\n"
      "point point3 (-2 -1 0) endpoint\npoint point4 (2 -1 0) endpoint\n"
      "polyline crossSection (point1 point2 point3 point4) isloop endpolyline\n"
      "sweep s1\n  crosssection crossSection endcrosssection\n"
      "  path myc mintorsion azimuth {expr $b_s_azimuth} twist {expr $b_s_twist} endpath\nendsweep\n"
      "instance sweepinst s1 endinstance\n";
  Scene s = Scene::from_text(text, "t.nome");
  for (const double twist : {0.0, 180.0, 360.0}) {
    INFO("twist " << twist);
    s.set_parameter(*s.find_parameter("b_s_twist"), twist);
    CHECK(s.warnings().empty());
    const TopologyReport r = topology(s.combined_soup());
    CHECK(r.borders == 0);
    CHECK(r.chi == 0);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
    CHECK(r.components.size() == 1);
  }
}

TEST_CASE("sweep_positions() gives exactly the positions of sweep()", "[scene]") {
  SweepOptions o;
  o.frames = FrameKind::minimal_torsion;
  o.is_path_closed = true;
  o.twist = 90;
  o.azimuth = 10;
  std::vector<PathSample> path = circle_path(12);
  path[3].scale = {2, 0.5};
  path[5].rotate = {5, 10, 30};
  const PolygonSoup soup = sweep(path, {&square_section, 1}, o).piece.soup;
  CHECK(sweep_positions(path, {&square_section, 1}, o).positions == soup.positions);
}

TEST_CASE("a sweep with every option is saved and read back to the same surface", "[scene]") {
  const std::string text =
      "bank b set az 30 -180 180 1 endbank\n" + std::string(square_points) +
      "point a (0 0 0) endpoint\npoint b (0 0 2) endpoint\npoint c (1 0 3) endpoint\npoint d (3 0 3) "
      "endpoint\n"
      "point e (4 1 3) endpoint\n"
      "controlpoint cb point b scale (1.5 1 0) rotate (0 0 20) reverse endcontrolpoint\n"
      "bspline p order 3 (a cb c d e) segs 12 endbspline\n"
      "sweep s crosssection sq reverse begincap endcap endcrosssection\n"
      "  path p mintorsion azimuth ($b_az + 180) twist 45 cutbegin cutend endpath brep TRIANGLES endsweep\n"
      "instance i s endinstance\n";
  const Scene s = Scene::from_text(text, "t.nome");
  const PolygonSoup& soup = s.instances()[0].geometry.soup;
  CHECK(soup.num_vertices() == 11 * 4);
  CHECK(soup.num_faces() == 10 * 4 * 2 + 2);
  const TopologyReport r = topology(soup);
  CHECK(r.borders == 0);
  CHECK(r.chi == 2);
  const Scene back = Scene::from_text(to_nome_text(s), "saved.nome");
  const PolygonSoup& again = back.instances()[0].geometry.soup;
  CHECK(again.positions == soup.positions);
  CHECK(again.face_vertices == soup.face_vertices);
  CHECK(again.face_names == soup.face_names);
}

// JIPCAD's file as it is: 11 circles swept along B-splines of 51 points each, each capped at one end.
TEST_CASE("JIPCAD's arts_expo__antcolony.nom: eleven tubes, each a disc", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("jipcad");
  const Scene s = test::load_scene_file(test::shared_examples_dir("jipcad") + "/arts_expo__antcolony.nom");
  REQUIRE(s.instances().size() == 11);
  for (const SceneInstance& instance : s.instances()) {
    INFO(instance.name);
    const TopologyReport r = topology(instance.geometry.soup);
    CHECK(r.components.size() == 1);
    CHECK(r.borders == 1);
    CHECK(r.chi == 1);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
  }
}

TEST_CASE("a sweep's names are a rule: its instance, the combined soup and the pipeline's mesh share it",
          "[scene]") {
  const std::string text = std::string(square_points) +
                           "point a (0 0 0) endpoint\npoint b (0 0 3) endpoint\npoint c (2 0 5) endpoint\n"
                           "polyline p (a b c) endpolyline\n"
                           "sweep s crosssection sq begincap endcap endcrosssection path p endpath endsweep\n"
                           "instance i s endinstance\n";
  const std::uint64_t made = Names::lists_made();
  const Scene scene = Scene::from_text(text, "t.nome");
  const PolygonSoup& placed = scene.instances().at(0).geometry.soup;
  PolygonSoup soup = scene.combined_soup();
  CHECK(soup.vertex_names.shares_with(placed.vertex_names));
  CHECK(soup.face_names.shares_with(placed.face_names));
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{soup, {}, {}});
  PipelineSettings scene_stage;
  scene_stage.stage = Stage::scene;
  const Mesh& mesh = pipeline.run(scene_stage);
  CHECK(mesh.vertex_names().shares_with(placed.vertex_names));
  CHECK(mesh.face_names().shares_with(placed.face_names));
  CHECK(Names::lists_made() == made);  // no name was made into a string on the way
  CHECK(soup.vertex_names[0] == "i_v0_0");
  CHECK(soup.vertex_names[11] == "i_v2_3");
  CHECK(soup.face_names[7] == "i_f1_3");
  CHECK(soup.face_names[8] == "i_begincap");
  CHECK(soup.face_names[9] == "i_endcap");
}
