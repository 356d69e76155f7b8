// The successor's (JIPCAD's) spelling beside the 2016 one: dialect detection and funnel/tunnel argument
// order, saving in the file's dialect, includes, out-of-range sliders, sharp weights and $time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/scene/parser.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"
#include "support/missing_point_scene.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("nome_dialect_" + name + "_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  return dir;
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

bool has_warning(const Scene& s, const std::string& part) {
  const std::vector<Diagnostic> warnings = s.warnings();
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const Diagnostic& d) { return d.message.find(part) != std::string::npos; });
}

}  // namespace

TEST_CASE("a file's dialect is decided by its first telling statement, and says which", "[scene]") {
  const Scene jip = Scene::from_text("bank b\n  set n 4 3 9 1\n  list (n)\nendbank\n", "j.nom");
  CHECK(jip.dialect().dialect == Dialect::jipcad);
  CHECK(jip.dialect().cue == "'list' in a bank at j.nom:3:3");
  const Scene loop = Scene::from_text(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint\npolyline l (a b) isloop endpolyline\n", "r.nome");
  CHECK(loop.dialect().dialect == Dialect::report2016);
  CHECK(loop.dialect().cue == "'isloop' in a polyline at r.nome:2:18");
  const Scene closed = Scene::from_text(
      "point a (0 0 0) endpoint point b (1 0 0) endpoint\npolyline l (a b) closed endpolyline\n", "c.nom");
  CHECK(closed.dialect().dialect == Dialect::jipcad);
  const Scene plain = Scene::from_text("point a (0 0 0) endpoint\n", "p.nome");
  CHECK(plain.dialect().dialect == Dialect::report2016);
  CHECK(plain.dialect().cue.empty());
  const Scene forced = Scene::from_text("point a (0 0 0) endpoint\n", "p.nome", {.dialect = Dialect::jipcad});
  CHECK(forced.dialect().dialect == Dialect::jipcad);
  CHECK(forced.dialect().cue == "--dialect");
}

TEST_CASE("funnel and tunnel read their arguments in the file's dialect", "[scene]") {
  const Scene report =
      Scene::from_text("funnel f (6 1 0.5 2) endfunnel\ninstance i f endinstance\n", "r.nome");
  const Scene jip = Scene::from_text(
      "bank b set s 6 3 9 1 list (s) endbank\nfunnel f (1 0.5 2 {expr $b.s}) endfunnel\n"
      "instance i f endinstance\n",
      "j.nom");
  CHECK(jip.combined_soup().positions == report.combined_soup().positions);
  CHECK(jip.combined_soup().num_faces() == 6);
  // The same text read the other way is another funnel (or none): the dialect matters.
  CHECK_THROWS_AS(Scene::from_text("funnel f (1 0.5 2 6) endfunnel\ninstance i f endinstance\n", "r.nome"),
                  SceneError);
  const Scene tunnel = Scene::from_text("tunnel t (1 0.5 2 5) endtunnel\ninstance i t endinstance\n", "t.nom",
                                        {.dialect = Dialect::jipcad});
  const Scene tunnel_2016 =
      Scene::from_text("tunnel t (5 1 0.5 2) endtunnel\ninstance i t endinstance\n", "t.nome");
  CHECK(tunnel.combined_soup().positions == tunnel_2016.combined_soup().positions);
}

TEST_CASE("saving keeps the file's dialect and reads back the same", "[scene]") {
  const Scene jip = Scene::from_text(
      "funnel f (1 0.5 2 6) endfunnel\npoint a (0 0 0) endpoint point b (1 0 0) endpoint\n"
      "polyline l (a b) endpolyline\ninstance i f endinstance\n",
      "j.nom", {.dialect = Dialect::jipcad});
  const std::string saved = to_nome_text(jip);
  CHECK_THAT(saved, Catch::Contains(jipcad_header));
  const Scene back = Scene::from_text(saved, "saved.nom");
  CHECK(back.dialect().dialect == Dialect::jipcad);
  CHECK_THAT(back.dialect().cue, Catch::Contains("nome-dialect"));
  CHECK(back.combined_soup().positions == jip.combined_soup().positions);

  const Scene listed = Scene::from_text(
      "bank b\n set n 1 0 2 1\n set m 1 0 2 1\n list (m)\nendbank\n"
      "point a (0 0 0) endpoint point c (1 0 0) endpoint\npolyline l (a c) closed endpolyline\n",
      "l.nom");
  REQUIRE(listed.banks().size() == 1);
  CHECK(listed.banks()[0].shown == std::vector<ParameterId>{ParameterId(1)});
  const std::string listed_saved = to_nome_text(listed);
  CHECK_THAT(listed_saved, Catch::Contains("    list (m)\n"));
  CHECK_THAT(listed_saved, Catch::Contains(" closed endpolyline"));
  const std::string report_saved = to_nome_text(Scene::from_text(
      "point a (0 0 0) endpoint point c (1 0 0) endpoint\npolyline l (a c) isloop endpolyline\n", "r.nome"));
  CHECK_THAT(report_saved, Catch::Contains(" isloop endpolyline"));
  CHECK_THAT(report_saved, !Catch::Contains("list") && !Catch::Contains(jipcad_header));
}

TEST_CASE("include reads files relative to the including one, nested, banks included", "[scene]") {
  const auto dir = scratch("include");
  write(dir / "parts" / "sliders.nom", "bank s\n  set n 5 3 9 1\n  list (n)\nendbank\n");
  write(dir / "parts" / "shape.nom",
        "include [sliders.nom] endinclude\nfunnel f (1 0.5 2 {expr $s.n}) endfunnel\n");
  write(dir / "main.nom", "include [parts/shape.nom] endinclude\ninstance i f endinstance\n");
  Scene s = read_scene(dir / "main.nom");
  CHECK(s.combined_soup().num_faces() == 5);
  CHECK(s.ast().included_files.size() == 2);
  s.set_parameter(*s.find_parameter("s_n"), 7);
  CHECK(s.combined_soup().num_faces() == 7);
  std::filesystem::remove_all(dir);
}

TEST_CASE("include without brackets reads the file its identifier names, as JIPCAD's tutorial writes it",
          "[scene]") {
  const auto dir = scratch("bare_include");
  write(dir / "z_inclSurfaces.nom",
        "point a (0 0 0) endpoint point b (2 0 0) endpoint point c (0 3 0) endpoint\n");
  write(dir / "bell.nom",
        "include z_inclSurfaces.nom endinclude\nface f (a b c) endface\ninstance i f endinstance\n");
  const Scene s = read_scene(dir / "bell.nom");
  REQUIRE(s.ast().included_files.size() == 1);
  CHECK(std::filesystem::path(s.ast().included_files[0]).filename() == "z_inclSurfaces.nom");
  CHECK(test::vertex_position(s, "i_b") == Vec3(2, 0, 0));
  CHECK(test::vertex_position(s, "i_c") == Vec3(0, 3, 0));
  // The bracketed form keeps working, and neither form is a bare number.
  write(dir / "bracketed.nom",
        "include [z_inclSurfaces.nom] endinclude\nface f (a b c) endface\ninstance i f endinstance\n");
  CHECK(test::vertex_position(read_scene(dir / "bracketed.nom"), "i_c") == Vec3(0, 3, 0));
  write(dir / "number.nom", "include 12 endinclude\n");
  CHECK_THROWS_WITH(read_scene(dir / "number.nom"),
                    Catch::Contains("number.nom:1:9: expected '[' or a file name"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("an include cycle is refused with the chain of files", "[scene]") {
  const auto dir = scratch("cycle");
  write(dir / "a.nom", "include [sub/b.nom] endinclude\n");
  write(dir / "sub" / "b.nom", "point p (0 0 0) endpoint\ninclude [../a.nom] endinclude\n");
  try {
    read_scene(dir / "a.nom");
    FAIL("the cycle was not refused");
  } catch (const SceneError& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::Contains("b.nom:2:1: include cycle: "));
    CHECK_THAT(what, Catch::Contains("a.nom -> ") && Catch::Contains("b.nom -> "));
  }
  write(dir / "missing.nom", "include [nowhere.nom] endinclude\n");
  CHECK_THROWS_WITH(read_scene(dir / "missing.nom"),
                    Catch::Contains("missing.nom:1:1: cannot read included file"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a slider's initial value outside its range is kept, with a warning", "[scene]") {
  Scene s = Scene::from_text(
      "bank b set n 12 3 10 1 endbank\nfunnel f ({expr $b_n} 1 0.5 2) endfunnel\n"
      "instance i f endinstance\n",
      "t.nome");
  CHECK(has_warning(s, "value 12 of 'b_n' is outside its slider range [3, 10]: kept until the slider"));
  CHECK(s.parameters().front().value == 12);
  CHECK(s.combined_soup().num_faces() == 12);
  s.set_parameter(scene::ParameterId(0), 10);
  CHECK(s.combined_soup().num_faces() == 10);
  CHECK_THROWS_AS(s.set_parameter(scene::ParameterId(0), 12), InvalidInputError);
}

TEST_CASE("sharp takes a weight and several chains, the weight as OpenSubdiv's sharpness", "[scene]") {
  const Scene s = Scene::from_text(
      "bank b set w 2 0 10 0.5 endbank\n"
      "point a (0 0 0) endpoint point c (1 0 0) endpoint point d (1 1 0) endpoint point e (0 1 0) endpoint\n"
      "mesh m face f (a c d e) endface\n  sharp 9 (a c d) endsharp\n  sharp {expr $b.w} (d e) (e a) "
      "endsharp\n"
      "endmesh\ninstance i m endinstance\n",
      "t.nom");
  const PolygonSoup soup = s.combined_soup();
  CHECK(soup.sharp_edges.size() == 4);
  CHECK(soup.sharp_edge_weights == std::vector<float>{9, 9, 2, 2});
  CHECK(s.warnings().empty());
  const std::string saved = to_nome_text(s);
  CHECK_THAT(saved, Catch::Contains("sharp 9 (a c d) endsharp") &&
                        Catch::Contains("sharp {expr $b_w} (e a) endsharp"));
}

TEST_CASE("$time and $frame are built-in parameters, 0 until set", "[scene]") {
  Scene s = Scene::from_text(
      "point p ({expr $time} {expr $frame} 0) endpoint\n"
      "point q (1 0 0) endpoint point r (0 1 0) endpoint\n"
      "face f (p q r) endface\ninstance i f endinstance\n",
      "t.nome");
  CHECK(s.combined_soup().positions[0] == Vec3(0, 0, 0));
  CHECK(s.parameters().empty());  // no slider
  CHECK_FALSE(s.find_parameter("time"));
  CHECK(s.set_clock(time_parameter, 2.5).size() == 1);
  s.set_clock(frame_parameter, 3);
  CHECK(s.combined_soup().positions[0] == Vec3(2.5, 3, 0));
  CHECK_THROWS_AS(s.set_clock("clock", 1), InvalidInputError);
}

TEST_CASE("the successor's tuples hold bare expressions, a sign after a space starts the next value",
          "[scene]") {
  const Scene s = Scene::from_text(
      "bank b set h 2 0 4 1 endbank\n"
      "point p (1/2 -1 2*$b.h) endpoint\npoint q (1 - 1, {expr $b.h} * 2, -(1)) endpoint\n"
      "point r (-1*{expr $b_h} sqrt(4) b.h) endpoint\nface f (p q r) endface\ninstance i f endinstance\n",
      "t.nom");
  const auto& positions = s.combined_soup().positions;
  REQUIRE(positions.size() == 3);
  CHECK(positions[0] == Vec3(0.5, -1, 4));
  CHECK(positions[1] == Vec3(0, 4, -1));
  CHECK(positions[2] == Vec3(-2, 2, 2));
  CHECK(s.ast().points[0].xyz[1].expr == no_index);  // a plain number stays a literal
}

TEST_CASE("in JIPCAD's dialect a face naming an unknown point is left out with a warning", "[scene]") {
  // JIPCAD skips points it cannot find; one of its example files relies on that. The 2016 dialect refuses.
  const std::string mesh(test::missing_point_scene);
  const Scene jip = Scene::from_text(mesh, "m.nom", {.dialect = Dialect::jipcad});
  REQUIRE(jip.instances().size() == 1);
  CHECK(jip.instances()[0].geometry.soup.num_faces() == 1);
  CHECK(jip.instances()[0].geometry.soup.face_names == std::vector<std::string>{"i_f1"});
  REQUIRE(jip.warnings().size() == 1);
  CHECK(jip.warnings()[0].to_string() == "m.nom:4:16: warning: unknown point 'x': face 'f2' left out");
  try {
    (void)Scene::from_text(mesh, "m.nome", {.dialect = Dialect::report2016});
    FAIL("the 2016 dialect accepted an unknown vertex");
  } catch (const SceneError& e) {
    CHECK_THAT(e.what(), Catch::Contains("m.nome:4:16: unknown vertex 'x'"));
  }
  // Outside a face a missing point stays an error in both dialects.
  CHECK_THROWS_WITH(Scene::from_text(mesh + "polyline l (i.a y) endpolyline\ninstance il l endinstance\n",
                                     "l.nom", {.dialect = Dialect::jipcad}),
                    Catch::Contains("l.nom:7:17: unknown point 'y'"));
}

TEST_CASE("a JIPCAD vertex path may name each instance's definition after it", "[scene]") {
  // `.i.m.b`, as JIPCAD's editor writes it, is the vertex `i.b`.
  const Scene s = Scene::from_text(
      "mesh m\n"
      "  point a (0 0 0) endpoint  point b (1 0 0) endpoint  point c (0 1 0) endpoint\n"
      "  face f (a b c) endface\n"
      "endmesh\n"
      "instance i m translate(0 0 2) endinstance\n"
      "polyline l (i.a .i.m.b) endpolyline\n"
      "instance il l endinstance\n",
      "p.nom", {.dialect = Dialect::jipcad});
  REQUIRE(s.instances().size() == 2);
  const Piece& line = s.instances()[1].geometry;
  REQUIRE(line.rims.size() == 1);
  REQUIRE(line.rims[0].vertices.size() == 2);
  CHECK(line.soup.positions[line.rims[0].vertices[0]] == Vec3(0, 0, 2));
  CHECK(line.soup.positions[line.rims[0].vertices[1]] == Vec3(1, 0, 2));
  CHECK(s.warnings().empty());
}
