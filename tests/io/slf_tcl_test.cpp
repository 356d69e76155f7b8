#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "nome/edit/scene_drag.hpp"
#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/scene/parser.hpp"
#include "nome/slide/read_slf.hpp"
#include "scene/scene_support.hpp"
#include "support/scratch_files.hpp"

using namespace nome;

namespace {

// A scene of one triangle whose coordinates are Tcl values over two sliders of SLIDE's library.
const char* const slider_scene =
    "tclinit {\n"
    "  source SLIDEUI.tcl\n"
    "  toplevel .w\n"
    "  CreateScale f .w r \"radius\" 2.5 1.0 10.0 0.5 1 horizontal\n"
    "  CreateScale f .w n \"count\" 3 1 9 1 1 horizontal\n"
    "}\n"
    "point a (0 0 0) endpoint\n"
    "point b ({expr $f_r} 0 0) endpoint\n"
    "point c (0 {expr $f_n / 2} 0) endpoint\n"
    "point d ({ -$f_r } {$f_n} 1) endpoint\n"
    "face x (a b c) endface face y (a c d) endface\n"
    "object o (x y) endobject\n"
    "group g instance o endinstance endgroup\n";

std::string refusal(const std::string& text, const slide::TclLimits& limits = {}) {
  try {
    (void)slide::read_slf_scene(text, test::scratch_path("nome_slf_tcl", "t.slf"), {}, limits);
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "no error";
}

// As the io layer reads a .slf file: its Tcl reads mesh files with read_polygons.
scene::Scene io_read_slf(const std::string& text, const std::filesystem::path& path) {
  std::ofstream(path) << text;
  return read_scene(path);
}

}  // namespace

TEST_CASE("a .slf file's Tcl makes its sliders and computes its braced values, again on every move", "[io]") {
  scene::Scene s = slide::read_slf_scene(slider_scene, test::scratch_path("nome_slf_tcl", "t.slf"));
  const auto r = s.find_parameter("w_f_r"), n = s.find_parameter("w_f_n");
  REQUIRE(r);
  REQUIRE(n);
  CHECK(s.parameters()[*r].value == 2.5);
  CHECK(s.parameters()[*r].min == 1.0);
  CHECK(s.parameters()[*r].max == 10.0);
  CHECK(s.parameters()[*r].step == 0.5);
  CHECK(s.parameters()[*r].label == "radius");
  CHECK(s.parameters()[*n].value == 3);
  CHECK(test::vertex_position(s, "g_o_b") == Vec3(2.5, 0, 0));
  // A slider of whole steps gives Tcl an integer, so `/` divides as SLIDE's Tcl did: 3 / 2 is 1.
  CHECK(test::vertex_position(s, "g_o_c") == Vec3(0, 1, 0));
  CHECK(test::vertex_position(s, "g_o_d") == Vec3(-2.5, 3, 1));
  // Read traces on the sliders' variables: the placement's values read both sliders, the scene's other
  // numbers none.
  CHECK(s.parameters_of_vertex("g_o_b") == std::vector<scene::ParameterId>{*r, *n});

  s.set_parameter(*n, 5);
  CHECK(test::vertex_position(s, "g_o_c") == Vec3(0, 2, 0));
  CHECK(test::vertex_position(s, "g_o_d") == Vec3(-2.5, 5, 1));
  s.set_parameter(*r, 4);
  CHECK(test::vertex_position(s, "g_o_b") == Vec3(4, 0, 0));
  s.set_parameter(*r, 2.5);
  s.set_parameter(*n, 3);
  CHECK(test::vertex_position(s, "g_o_c") == Vec3(0, 1, 0));
  CHECK(test::vertex_position(s, "g_o_d") == Vec3(-2.5, 3, 1));
}

TEST_CASE("SLIDE's library: SLF_PI, degree helpers and the slideui package's own slider form", "[io]") {
  const scene::Scene s = slide::read_slf_scene(
      "tclinit {\n"
      "  package require slideui\n"
      "  set param(v0) 0.75\n"
      "  toplevel .ui\n"
      "  CreateScale .ui s_v0 param(v0) \"v0\" 0.5 1.0 0.05\n"
      "}\n"
      "point a (0 0 0) endpoint point b ({expr $param(v0)} 0 0) endpoint\n"
      "point c (0 {expr sin([DegToRad 90])} {expr $SLF_PI}) endpoint\n"
      "face x (a b c) endface object o (x) endobject group g instance o endinstance endgroup\n",
      test::scratch_path("nome_slf_tcl", "t.slf"));
  const auto v0 = s.find_parameter("ui_param_v0");
  REQUIRE(v0);
  CHECK(s.parameters()[*v0].value == 0.75);
  CHECK(s.parameters()[*v0].min == 0.5);
  CHECK(test::vertex_position(s, "g_o_b").x == 0.75);
  CHECK(test::vertex_position(s, "g_o_c").y == Approx(1.0));
  CHECK(test::vertex_position(s, "g_o_c").z == Approx(3.14159265358979));
}

TEST_CASE("a scale's command runs once the scene is read and again whenever its slider moves", "[io]") {
  scene::Scene s = slide::read_slf_scene(
      "tclinit {\n"
      "  package require slideui\n"
      "  toplevel .w\n"
      "  proc Derive {v} { global derived; set derived [expr {$v * 10}] }\n"
      "  set k 2\n"
      "  CreateScale .w s_k k \"k\" 1 5 1 Derive\n"
      "}\n"
      "point a (0 0 0) endpoint point b ({expr $derived} 0 0) endpoint point c (0 1 0) endpoint\n"
      "face x (a b c) endface object o (x) endobject group g instance o endinstance endgroup\n",
      test::scratch_path("nome_slf_tcl", "t.slf"));
  const auto k = s.find_parameter("w_k");
  REQUIRE(k);
  CHECK(test::vertex_position(s, "g_o_b").x == 20);
  CHECK(s.parameters_of_vertex("g_o_b") == std::vector<scene::ParameterId>{*k});
  s.set_parameter(*k, 3);
  CHECK(test::vertex_position(s, "g_o_b").x == 30);
  s.set_parameter(*k, 2);
  CHECK(test::vertex_position(s, "g_o_b").x == 20);
}

TEST_CASE("`source` reads the Tcl file beside the scene and nothing outside its folder", "[io]") {
  const std::filesystem::path scene_file = test::scratch_path("nome_slf_source", "s.slf");
  std::ofstream(scene_file.parent_path() / "helper.tcl") << "proc Twice {x} { expr {2 * $x} }\n";
  const scene::Scene s = slide::read_slf_scene(
      "tclinit { source helper.tcl }\n"
      "point a (0 0 0) endpoint point b ({Twice 1.5} 0 0) endpoint point c (0 1 0) endpoint\n"
      "face x (a b c) endface object o (x) endobject group g instance o endinstance endgroup\n",
      scene_file);
  CHECK(test::vertex_position(s, "g_o_b").x == 3);
  // Braces escaped with a backslash do not close a Tcl block (Tcl's rule).
  const scene::Scene escaped = slide::read_slf_scene(
      "tclinit { set s \"a\\}b\" }\n"
      "point a ({string length $s} 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
      "face x (a b c) endface object o (x) endobject group g instance o endinstance endgroup\n",
      scene_file);
  CHECK(test::vertex_position(escaped, "g_o_a").x == 3);
  CHECK_THAT(
      refusal("tclinit { source ../../etc/passwd }\n"),
      Catch::Contains("t.slf:1:9: Tcl: couldn't read file \"../../etc/passwd\": a scene reads files in "
                      "its own folder only"));
  CHECK_THAT(refusal("tclinit { source missing.tcl }\n"),
             Catch::Contains("couldn't read file \"missing.tcl\": no such file beside the scene"));
}

TEST_CASE("a .slf file's Tcl runs safe: no exec, no files, runaway loops stopped, errors located", "[io]") {
  CHECK_THAT(refusal("point a (0 0 0) endpoint\n"
                     "tclinit {\n"
                     "  set x 1\n"
                     "  exec rm -rf /tmp/x\n"
                     "}\n"),
             Catch::Contains("t.slf:4:1: Tcl: invalid command name \"exec\""));
  CHECK_THAT(refusal("tclinit { open /etc/passwd w }\n"), Catch::Contains("invalid command name \"open\""));
  CHECK_THAT(refusal("tclinit { socket example.com 80 }\n"),
             Catch::Contains("invalid command name \"socket\""));
  CHECK_THAT(refusal("tclinit { while 1 {} }\n", {std::chrono::milliseconds(200), 100000}),
             Catch::Contains("t.slf:1:9: Tcl: time limit exceeded"));
  CHECK_THAT(refusal("tclinit { proc f {} {}; while 1 { f } }\n", {std::chrono::milliseconds(5000), 10000}),
             Catch::Contains("t.slf:1:9: Tcl: command count limit exceeded"));
  CHECK_THAT(refusal("point a ({expr 1 / 0} 0 0) endpoint face x (a a a) endface object o (x) endobject\n"),
             Catch::Contains("t.slf:1:10: Tcl: divide by zero"));
  CHECK_THAT(refusal("point a ({list 1 2} 0 0) endpoint face x (a a a) endface object o (x) endobject\n"),
             Catch::Contains("t.slf:1:10: Tcl gave '1 2' where a number is expected"));
  CHECK_THAT(refusal("tclinit { slide create point p {0 0} }\n"),
             Catch::Contains("t.slf:1:9: Tcl: a point takes 3 coordinates, found 2"));
  CHECK_THAT(refusal("tclinit { slide create sphere s }\n"),
             Catch::Contains("'slide create sphere' is not supported yet"));
  CHECK_THAT(refusal("tclinit { set x {1 2 }\n"), Catch::Contains("t.slf:1:9: this '{' is never closed"));
}

TEST_CASE("`slide create` and `slide delete` in a tclinit block build the scene, Tcl values included",
          "[io]") {
  scene::Scene s = slide::read_slf_scene(
      "group gWorld endgroup\n"
      "tclinit {\n"
      "  source SLIDEUI.tcl\n"
      "  toplevel .w\n"
      "  CreateScale f .w h \"height\" 2 1 5 1 1 horizontal\n"
      "  slide create point p0 {0 0 0}\n"
      "  slide create point p1 [list 1 0 0]\n"
      "  slide create point p2 [list 0 [list expr {$f_h} / 2.0] 0]\n"
      "  slide create point junk {5 5 5}\n"
      "  slide delete point junk\n"
      "  slide create face tri {p0 p1 p2}\n"
      "  slide create object obj {tri}\n"
      "  foreach {id z} {i1 0 i2 3} { slide create instance $id gWorld obj -xforms [list [list translate (0 "
      "0 $z)]] }\n"
      "  slide create instance i3 gWorld obj -xforms {{rotate (0 0 1) $f_h*45}}\n"
      "}\n",
      test::scratch_path("nome_slf_tcl", "t.slf"));
  CHECK(s.ast().points.size() == 3);
  CHECK(test::vertex_position(s, "gWorld_i2_p2") == Vec3(0, 1, 3));
  CHECK(test::vertex_position(s, "gWorld_i3_p1").x == Approx(0).margin(1e-12));
  CHECK(test::vertex_position(s, "gWorld_i3_p1").y == Approx(1));
  const auto h = s.find_parameter("w_f_h");
  REQUIRE(h);
  s.set_parameter(*h, 4);
  CHECK(test::vertex_position(s, "gWorld_i2_p2") == Vec3(0, 2, 3));
  CHECK(test::vertex_position(s, "gWorld_i3_p1").x == Approx(-1));
  CHECK_THAT(refusal("group g endgroup\n"
                     "tclinit {\n"
                     "  slide create group g2\n"
                     "  slide create instance i g missing\n"
                     "  slide create instance i nowhere g2\n"
                     "}\n"),
             Catch::Contains("t.slf:5:1: Tcl: slide create instance: no group named \"nowhere\""));
}

TEST_CASE("SLIDE's parselib: CreateSTLObject reads an STL file beside the scene into an object", "[io]") {
  const std::filesystem::path scene_file = test::scratch_path("nome_slf_stl", "s.slf");
  {
    std::ofstream stl(scene_file.parent_path() / "tet.stl");
    stl << "solid tet\n";
    const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
      stl << "facet normal 0 0 0\nouter loop\n";
      for (int k : f) stl << "vertex " << p[k][0] << " " << p[k][1] << " " << p[k][2] << "\n";
      stl << "endloop\nendfacet\n";
    }
    stl << "endsolid tet\n";
  }
  const std::string text =
      "tclinit {\n"
      "  package require parselib\n"
      "  set foo [CreateSTLObject brep tet.stl]\n"
      "  slide create group gBrep\n"
      "  slide create instance bogus gBrep $foo\n"
      "}\n"
      "group gRoot instance gBrep endinstance instance brep id again translate (2 0 0) endinstance "
      "endgroup\n";
  const scene::Scene s = io_read_slf(text, scene_file);
  REQUIRE(s.instances().size() == 1);
  CHECK(s.instances()[0].name == "gRoot");
  // The object through the group Tcl made, and the group of the file's name beside it.
  CHECK(s.instances()[0].geometry.soup.num_vertices() == 8);
  CHECK(s.instances()[0].geometry.soup.num_faces() == 8);
  Vec3 sum(0.0);
  for (int v = 0; v < 4; ++v) sum += test::vertex_position(s, "gRoot_gBrep_bogus_brep_v" + std::to_string(v));
  CHECK(sum == Vec3(1, 1, 1));
  CHECK(test::vertex_position(s, "gRoot_again_obrep_brep_v0").x >= 2);
  CHECK_THAT(refusal("tclinit { CreateSTLObject x ../elsewhere.stl }\n"),
             Catch::Contains("a scene reads files in its own folder only"));
}

TEST_CASE("tclinit belongs to .slf files: a .nome file refuses it", "[scene]") {
  scene::Diagnostics d("t.nome");
  (void)scene::parse_nome("tclinit { set x 1 }\n", d);
  REQUIRE_FALSE(d.all().empty());
  CHECK_THAT(d.all()[0].to_string(),
             Catch::Contains("'tclinit' runs SLIDE's Tcl, read from .slf files only"));
}

TEST_CASE("SLIDE's render statements: the render root is what is drawn; cameras and lights place nothing",
          "[io]") {
  const scene::Scene s = slide::read_slf_scene(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
      "face x (a b c) endface\n"
      "object o (x) solid SLF_SOLID shading SLF_FLAT endobject\n"
      "object unused (x) endobject\n"
      "camera cam projection SLF_PERSPECTIVE frustum (-0.2 -0.2 -2) (0.2 0.2 -0.01) endcamera\n"
      "light sun type SLF_DIRECTIONAL color (1 1 1) endlight\n"
      "light amb type SLF_AMBIENT color (0.2 0.2 0.2) endlight\n"
      "group world\n"
      "  lod { expr $SLF_FULL }\n"
      "  instance o id io shading SLF_FLAT translate (0 0 1) endinstance\n"
      "  instance sun id isun lookat eye (1 1 1) target (0 0 0) up (0 1 0) endlookat endinstance\n"
      "endgroup\n"
      "group gCam instance cam id iCam translate (0 0 5) endinstance endgroup\n"
      "window Window background (0.3 0.6 0.3) endwindow\n"
      "viewport vp Window endviewport\n"
      "render vp gCam.iCam.cam world light world.isun.sun light amb endrender\n",
      test::scratch_path("nome_slf_tcl", "t.slf"));
  REQUIRE(s.instances().size() == 1);
  CHECK(s.instances()[0].name == "world");
  CHECK(test::vertex_position(s, "world_io_b") == Vec3(1, 0, 1));
  const scene::RenderDefaults look = s.render_defaults();
  REQUIRE(look.background);
  CHECK(look.background->g == Approx(0.6f));
  CHECK(look.camera_projection == "SLF_PERSPECTIVE");
  CHECK(look.camera_frustum == std::vector<double>{-0.2, -0.2, -2, 0.2, 0.2, -0.01});
  // The instanced light shines from its lookat's eye to its target.
  REQUIRE(look.lights.size() == 1);
  CHECK(look.lights[0].kind == scene::SceneLight::Kind::directional);
  CHECK(look.lights[0].direction.x == Approx(-1 / std::sqrt(3.0)));
  CHECK(look.lights[0].direction.z == Approx(-1 / std::sqrt(3.0)));
  CHECK_THAT(
      refusal("point a (0 0 0) endpoint face x (a a a) endface object o (x) endobject\n"
              "group g instance o lookat eye (1 1 1) target (0 0 0) up (0 1 0) endlookat endinstance "
              "endgroup\n"),
      Catch::Contains("t.slf:2:20: not supported yet: lookat on 'o', which is not a camera or a light"));
}

TEST_CASE("a SLIDE scene drags as a .nome scene does: its numbers, and the Tcl sliders behind its values",
          "[io]") {
  const std::string path = test::scratch_path("nome_slf_tcl", "drag.slf");
  const scene::Scene s = slide::read_slf_scene(slider_scene, path);
  const std::string a = s.resolve_vertex_name("a"), b = s.resolve_vertex_name("b");
  SceneDrag literal(s, slider_scene, {{a}, {}});
  const std::string moved = replaced_text(slider_scene, literal.move(Vec3(0.25, -1, 2)).replacements);
  std::string expected = slider_scene;
  expected.replace(expected.find("point a (0 0 0)"), 15, "point a (0.25 -1 2)");
  CHECK(moved == expected);
  const scene::Scene again = slide::read_slf_scene(moved, path);
  CHECK(test::vertex_position(again, a) == Vec3(0.25, -1, 2));

  SceneDrag slider(s, slider_scene, {{b}, {}});
  CHECK(slider.description() == "slider w_f_r");
  const DragStep step = slider.move(Vec3(1, 0, 0));
  REQUIRE(step.sliders.size() == 1);
  CHECK(step.sliders[0].second == 3.5);
  CHECK(step.slider_miss < 1e-12);
}
