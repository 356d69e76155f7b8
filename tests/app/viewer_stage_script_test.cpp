#include <catch2/catch.hpp>

#include <fstream>
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
