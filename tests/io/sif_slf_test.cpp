#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/io/sif.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "scene/scene_support.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"

using namespace nome;

namespace {

TopologyReport sif_report(const std::string& file, bool quads = false) {
  return topology_report(build_mesh(read_sif(test::originals_dir() + file, {quads, 20})));
}

}  // namespace

TEST_CASE("SIF files of the original programs read with their topology", "[io]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const TopologyReport kb8 = sif_report("KB8mesh.sif");
  CHECK(kb8.vertices == 20);
  CHECK(kb8.faces == 32);
  CHECK(kb8.borders == 2);
  const TopologyReport borromean = sif_report("borromean.sif");
  CHECK(borromean.components.size() == 3);
  CHECK(borromean.faces == 192);
  for (const ComponentTopology& c : borromean.components) CHECK((c.borders == 2 && c.chi == 0));
  const TopologyReport zero = sif_report("zero.sif");
  CHECK(zero.components.size() == 2);
  CHECK(sif_report("Tetra.sif").faces == 96);
  CHECK(sif_report("arcA.sif").faces == 256);
}

TEST_CASE("pairing triangles into quads keeps the topology", "[io]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  for (const char* file : {"Tetra.sif", "arcA.sif", "borromean.sif", "zero.sif", "KB8mesh.sif"}) {
    INFO(file);
    const TopologyReport t = sif_report(file), q = sif_report(file, true);
    CHECK(q.chi == t.chi);
    CHECK(q.borders == t.borders);
    CHECK(q.orientable == t.orientable);
    CHECK(q.components.size() == t.components.size());
    CHECK(q.vertices == t.vertices);
    CHECK(t.faces - q.faces == t.edges - q.edges);  // each pair removes one face and one edge
  }
  CHECK(sif_report("arcA.sif", true).faces == 128);  // a strip of coplanar pairs: every triangle paired
}

TEST_CASE("pairing prefers the flattest, squarest pair and refuses folds and non-convex quads", "[io]") {
  // A unit square split along a diagonal, and a third triangle folded up at 90 degrees.
  PolygonSoup s;
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 1, 1)})
    s.add_vertex(p);
  s.add_face({0, 1, 2});
  s.add_face({0, 2, 3});
  s.add_face({3, 2, 4});
  const PolygonSoup q = pair_triangles(s, 20);
  REQUIRE(q.num_faces() == 2);
  CHECK(q.face_offsets[1] == 4);
  PolygonSoup dart;  // a non-convex union: the shared edge is the outside of the dart
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 0.2, 0), Vec3(0, 2, 0)}) dart.add_vertex(p);
  dart.add_face({0, 1, 2});
  dart.add_face({0, 2, 3});
  CHECK(pair_triangles(dart, 20).num_faces() == 2);
}

// A long thin triangle with two flat neighbours: one makes a 4 x 1 rectangle (right angles), the other a
// kite with no right angle. The rectangle wins, whatever order the faces come in.
TEST_CASE("pairing measures each corner of a quad between its two sides", "[io]") {
  PolygonSoup s;
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 1, 0), Vec3(0, 1, 0), Vec3(2, -2, 0)}) s.add_vertex(p);
  s.add_face({0, 1, 2});  // the thin triangle
  s.add_face({1, 0, 4});  // below it: the kite, listed first
  s.add_face({0, 2, 3});  // above it: the rectangle
  const PolygonSoup q = pair_triangles(s, 20);
  REQUIRE(q.num_faces() == 2);
  std::vector<Index> quad;
  for (Index f = 0; f < q.num_faces(); ++f)
    if (q.face_offsets[f + 1] - q.face_offsets[f] == 4)
      quad.assign(q.face_vertices.begin() + q.face_offsets[f],
                  q.face_vertices.begin() + q.face_offsets[f + 1]);
  std::sort(quad.begin(), quad.end());
  CHECK(quad == std::vector<Index>{0, 1, 2, 3});
}

TEST_CASE("malformed SIF says where and what was expected", "[io]") {
  auto error = [](const std::string& text) {
    try {
      parse_sif(text, "t.sif");
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(error("(SIF_SFF 2 0 (solid (shell (vertices 2 (v 0 0 0)) )))") ==
        "t.sif:1:49: expected '(v x y z)' (2 vertices announced at 1:28), found ')'");
  CHECK(error("(SIF_SFF 2 0 (solid (shell (vertices 3 (v 0 0 0) (v 1 0 0) (v 0 1 0)) (triangles 1 (t 0 1 "
              "3)))))") == "t.sif:1:91: vertex index 3 out of range: the shell has 3 vertices");
  CHECK(error("(SOF 2 0)") == "t.sif:1:2: expected 'SIF_SFF', found 'SOF'");
  CHECK(error("(SIF_SFF 2 0 (solid (shell (vertices 1 (v 0 x 0)))))") ==
        "t.sif:1:45: expected a number, found 'x'");
  CHECK(error("(SIF_SFF 2 0 (* open") == "t.sif:1:14: unclosed comment: '(*' without '*)'");
}

TEST_CASE("the .slf subset reads points, faces, objects, groups and instances", "[io]") {
  const std::string dir = test::scratch_path("nome_slf_test", "").parent_path();
  std::ofstream(dir + "/cube.slf")
      << "surface Y color (1 1 0) endsurface\n"
         "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint\n"
         "point d (0 1 0) endpoint\n"
         "face x (a b c d) endface\n"
         "object o (x) endobject\n"
         "group g instance o id first surface Y endinstance\n"
         "  instance o id second translate (0 0 2) endinstance endgroup\n";
  const scene::Scene s = read_scene(dir + "/cube.slf");
  REQUIRE(s.instances().size() == 1);
  CHECK(s.instances()[0].name == "g");
  CHECK(test::vertex_position(s, "g_second_a").z == 2);
  REQUIRE(s.warnings().size() == 2);
  CHECK_THAT(
      s.warnings()[0].to_string(),
      Catch::EndsWith("cube.slf:1:1: warning: surface 'Y' ignored: colours of .slf files are not read"));
}

TEST_CASE("minSubdiv.slf opens: its subdivision node sets the level, a slider of its Tcl moves it", "[io]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  scene::Scene s = read_scene(test::originals_dir() + "minSubdiv.slf");
  REQUIRE(s.instances().size() == 1);
  CHECK(s.instances()[0].name == "gRoot");
  CHECK(s.instances()[0].geometry.soup.num_vertices() == 8);
  CHECK(s.instances()[0].geometry.soup.num_faces() == 6);
  const auto level = s.find_parameter("ui_oSubdivision_subdivisions");
  REQUIRE(level);
  CHECK(s.parameters()[*level].max == 6);
  CHECK(s.stage_settings().subdivision_levels == 1);
  s.set_parameter(*level, 3);
  CHECK(s.stage_settings().subdivision_levels == 3);
}

TEST_CASE("assets/mobius_band.sif: a single-sided band whose triangles all pair into quads", "[io]") {
  const std::string file = std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.sif";
  const TopologyReport t = topology_report(build_mesh(read_sif(file)));
  CHECK(t.faces == 48);
  CHECK(t.borders == 1);
  CHECK_FALSE(t.orientable);
  const TopologyReport q = topology_report(build_mesh(read_sif(file, {true, 20})));
  CHECK(q.faces == 24);
  CHECK(q.chi == 0);
  CHECK(q.borders == 1);
  CHECK_FALSE(q.orientable);
}
