#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/viewer_support.hpp"

using namespace nome;
using nome::test::assets;
using nome::test::logged_states;
using nome::test::run_window;
using nome::test::write_script;

// The viewer's own commands moving between stages and levels, as a user clicks them: every state is
// shown without an error, and the same settings show the same mesh each time they come back.
TEST_CASE("the viewer turns the offset off and on again, levels changed between, and shows the solid",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_offset_again");
  const std::string steps[] = {"offset 0.05", "offset 0",    "offset 0.05", "subdiv 1", "offset 0.05",
                               "offset 0",    "offset 0.05", "subdiv 2",    "offset 0", "offset 0.04",
                               "offset 0",    "subdiv 2",    "offset 0.05"};
  std::string script;
  for (const std::string& step : steps) script += step + "\nstate\n";
  const std::string path = write_script(dir, script + "quit\n");
  for (const char* file : {"torus.obj", "klein_bottle.obj", "mobius_band.obj", "grid.obj"}) {
    INFO(file);
    const auto r = run_window(assets + file + " --script " + path);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.err, !Catch::Contains("error:"));
    const std::vector<test::ViewerState> states = logged_states(r.err);
    REQUIRE(states.size() == std::size(steps));
    // offset 0.05 at two levels, the first and third steps the same solid, the last the same as them.
    CHECK(states[0].stage == "offset");
    CHECK(states[1].stage == "subdivided");
    CHECK(states[2].stage == "offset");
    CHECK(states[2].faces == states[0].faces);
    CHECK(states[12].faces == states[0].faces);
    CHECK(states[0].borders == 0);  // a closed solid, whatever the surface
    CHECK(states[2].borders == 0);
    CHECK(states[4].faces < states[0].faces);  // one level fewer
    CHECK(states[6].faces == states[4].faces);
    CHECK(states[9].faces == states[0].faces);
    CHECK(states[9].stage == "offset");
  }
}

TEST_CASE("a slider moved to a size past the budget is refused and put back, with the reason in the log",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_slider_budget");
  const std::string scene = dir + "/rings.nome";
  std::ofstream(scene) << "bank b\n set n 8 3 100000 1\nendbank\n"
                          "torus t (2 0.5 360 0 360 {expr $b.n} {expr $b.n}) endtorus\n"
                          "instance i t endinstance\n";
  const std::string path = write_script(dir, "state\nset b_n 30000\nstate\nset b_n 10\nstate\nquit\n");
  const auto r = run_window(scene + " --script " + path);
  INFO(r.err);
  CHECK_THAT(r.err, Catch::Contains("rings.nome:4:7: torus 't' would make about 900000000 faces"));
  const std::vector<test::ViewerState> states = logged_states(r.err);
  REQUIRE(states.size() == 3);
  CHECK(states[0].faces == 64);
  CHECK(states[1].faces == 64);  // put back: the shape of n = 8
  CHECK(states[2].faces == 100);
}

// The viewer opens a scene at the stage its blocks ask for: the highest subdivision level of several
// blocks, the thickest offset; the script's `subdiv` and `offset` (the control panel's) then win over them.
// Measured on what the viewer exports: a unit square in z = 0 thickened by D spans 2 D in z.
TEST_CASE("the viewer opens at the stage and levels the scene's blocks ask for, and its own settings win",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_stage_blocks");
  const std::string square =
      "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
      "mesh m face f (a b c d) endface endmesh\n";
  auto thickness = [](const std::string& obj) {
    std::ifstream in(obj);
    double low = 1e9, high = -1e9;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("v ", 0) == 0) {
        std::istringstream words(line.substr(2));
        double x = 0, y = 0, z = 0;
        words >> x >> y >> z;
        low = std::min(low, z);
        high = std::max(high, z);
      }
    return high - low;
  };

  // Levels 1 and 2 and offsets 0.1 and 0.3, the larger of each in the second block.
  std::ofstream(dir + "/blocks.nom") << square
                                     << "subdivision s1 sd_level 1 instance i m endinstance endsubdivision\n"
                                        "subdivision s2 sd_level 2 endsubdivision\n"
                                        "offset o1 height 0.1 endoffset\noffset o2 height 0.3 endoffset\n";
  const std::string script =
      write_script(dir, "state\nexport " + dir + "/own.obj\noffset 0.05\nstate\nexport " + dir +
                            "/thin.obj\nsubdiv 1\nstate\noffset 0\nstate\nsubdiv 0\nstate\nquit\n");
  const auto r = run_window(dir + "/blocks.nom --script " + script);
  INFO(r.err);
  CHECK(r.status == 0);
  const std::vector<test::ViewerState> states = logged_states(r.err);
  REQUIRE(states.size() == 5);
  // Two sheets of 16 quads and a rim quad on each of the 16 border edges.
  CHECK(states[0].stage == "offset");
  CHECK(states[0].faces == 2 * 16 + 16);
  CHECK(thickness(dir + "/own.obj") == Approx(0.6).margin(1e-6));
  CHECK(states[1].stage == "offset");
  CHECK(states[1].faces == 2 * 16 + 16);
  CHECK(thickness(dir + "/thin.obj") == Approx(0.1).margin(1e-6));
  CHECK(states[2].faces == 2 * 4 + 8);
  CHECK(states[3].stage == "subdivided");
  CHECK(states[3].faces == 4);
  CHECK(states[4].faces == 1);

  // Subdivision blocks alone: the subdivided stage, at the highest level whichever block comes first.
  for (const char* blocks : {"subdivision s1 sd_level 2 instance i m endinstance endsubdivision\n"
                             "subdivision s2 sd_level 1 endsubdivision\n",
                             "subdivision s1 sd_level 1 instance i m endinstance endsubdivision\n"
                             "subdivision s2 sd_level 2 endsubdivision\n"}) {
    INFO(blocks);
    std::ofstream(dir + "/levels.nom") << square << blocks;
    const auto levels = run_window(dir + "/levels.nom --script " + write_script(dir, "state\nquit\n"));
    INFO(levels.err);
    const std::vector<test::ViewerState> shown = logged_states(levels.err);
    REQUIRE(shown.size() == 1);
    CHECK(shown[0].stage == "subdivided");
    CHECK(shown[0].faces == 16);
  }
}

// SLIDE's subdivision node reads its level from a slider of the file's Tcl: the viewer subdivides at that
// level when the file opens and follows the slider when it moves.
TEST_CASE("a SLIDE scene's subdivision slider sets the viewer's level, there and back", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_slide_level");
  const std::string scene = dir + "/tetra.slf";
  std::ofstream(scene) << "tclinit {\n"
                          "  package require slideui\n"
                          "  toplevel .slfWindow.ui\n"
                          "  CreateSLIDESubdivisionObject oSubdivision\n"
                          "  pack [CreateSLIDESubdivisionUI .slfWindow.ui oSubdivision]\n"
                          "}\n"
                          "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
                          "point d (0 0 1) endpoint\n"
                          "face f1 (a c b) endface face f2 (a b d) endface face f3 (a d c) endface\n"
                          "face f4 (b c d) endface\n"
                          "object tetra (f1 f2 f3 f4) solid SLF_SOLID endobject\n"
                          "subdivision oSubdiv type {expr $oSubdivision(type)}\n"
                          "  subdivisions {expr $oSubdivision(subdivisions)}\n"
                          "  instance tetra endinstance\n"
                          "endsubdivision\n"
                          "group gRoot instance oSubdiv endinstance endgroup\n";
  const std::string path = write_script(
      dir,
      "state\nset ui_oSubdivision_subdivisions 2\nstate\nset ui_oSubdivision_subdivisions 1\nstate\nquit\n");
  const auto r = run_window(scene + " --script " + path);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.err, !Catch::Contains("error:"));
  const std::vector<test::ViewerState> states = logged_states(r.err);
  REQUIRE(states.size() == 3);
  CHECK(states[0].stage == "subdivided");
  CHECK(states[0].faces == 12);  // each triangle makes 3 quads
  CHECK(states[1].faces == 48);
  CHECK(states[2].faces == 12);
  CHECK(states[2].borders == 0);
}
