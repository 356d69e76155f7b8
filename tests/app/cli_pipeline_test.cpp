#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"

using nome::test::run_nome;

namespace {
using nome::test::assets;
}

TEST_CASE("nome export --subdiv --offset turns a Möbius band into a closed torus-shaped STL", "[app]") {
  const std::string dir = nome::test::scratch_dir("pipeline");
  const auto r =
      run_nome("export " + assets + "mobius_band.obj --subdiv 3 --offset 0.05 -o " + dir + "/band.stl");
  REQUIRE(r.status == 0);
  const auto info = run_nome("info " + dir + "/band.stl --json");
  CHECK(info.status == 0);
  CHECK_THAT(info.out,
             Catch::Contains("\"chi\": 0, \"orientable\": true, \"borders\": 0, \"components\": 1"));
  CHECK_THAT(info.out, Catch::Contains("\"mobius_edges\": 0"));
  CHECK_THAT(info.out, Catch::Contains("\"genus\": 1"));
}

TEST_CASE("nome info reports the pipeline's result", "[app]") {
  // The cube: 6 faces -> 24 -> 96 quads; both rules give the same topology.
  for (const char* rule : {"classic", "report"}) {
    const auto r = run_nome("info " + assets + "cube.obj --json --subdiv 2 --rule " + rule);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("\"vertices\": 98, \"edges\": 192, \"faces\": 96, \"chi\": 2"));
    // Counted on the cube itself, and said so.
    CHECK_THAT(r.out, Catch::Contains("\"derived_over_levels\": 2"));
  }
  const auto text = run_nome("info " + assets + "cube.obj --subdiv 2");
  CHECK_THAT(text.out, Catch::Contains("counted on the mesh before the last 2 subdivision levels") &&
                           Catch::Contains("vertices 98, edges 192, faces 96"));
  // A disk thickens into a sphere; subdivision after keeps it one.
  const auto disk = run_nome("info " + assets + "grid.obj --json --offset 0.1 --subdiv-after 1");
  CHECK(disk.status == 0);
  CHECK_THAT(disk.out, Catch::Contains("\"chi\": 2, \"orientable\": true, \"borders\": 0"));
  // A Klein bottle thickens into a torus.
  const auto klein = run_nome("info " + assets + "klein_bottle.obj --json --subdiv 1 --offset 0.02");
  CHECK(klein.status == 0);
  CHECK_THAT(klein.out,
             Catch::Contains("\"chi\": 0, \"orientable\": true, \"borders\": 0, \"components\": 1"));
}

TEST_CASE("nome info of an offset counts on the surface under it: the exported solid's report", "[app]") {
  const std::string dir = nome::test::scratch_dir("offset_info");
  for (const char* shape : {"mobius_band.obj", "torus.obj", "grid.obj", "klein_bottle.obj"}) {
    CAPTURE(shape);
    const std::string options = " --subdiv 1 --offset 0.02";
    const auto derived = run_nome("info " + assets + shape + options + " --json");
    REQUIRE(derived.status == 0);
    const std::string said = ", \"derived_over_offset\": true";
    REQUIRE(derived.out.find(said) != std::string::npos);
    REQUIRE(run_nome("export " + assets + shape + options + " -o " + dir + "/solid.obj").status == 0);
    const auto counted = run_nome("info " + dir + "/solid.obj --json");
    REQUIRE(counted.status == 0);
    std::string expected = derived.out;
    expected.erase(expected.find(said), said.size());
    CHECK(counted.out == expected);
  }
  CHECK_THAT(run_nome("info " + assets + "torus.obj --offset 0.02").out,
             Catch::Contains("counted on the surface under the offset"));
}

TEST_CASE("nome info --boundary none leaves out the faces at the border, edge-and-corner keeps them",
          "[app]") {
  // The 4x4 grid: its inner 2x2 faces have no border vertex; one level makes each four.
  const std::string grid = assets + "grid.obj --json --subdiv 1 --boundary ";
  const auto none = run_nome("info " + grid + "none");
  CHECK(none.status == 0);
  CHECK_THAT(none.out, Catch::Contains("\"vertices\": 25, \"edges\": 40, \"faces\": 16, \"chi\": 1"));
  const auto corners = run_nome("info " + grid + "edge-and-corner");
  CHECK(corners.status == 0);
  CHECK_THAT(corners.out, Catch::Contains("\"faces\": 64, \"chi\": 1"));
}

TEST_CASE("pipeline options out of range are usage errors, oversized results need --force", "[app]") {
  const std::string cube = assets + "cube.obj";
  CHECK(nome::test::run_nome_in_process("info " + cube + " --subdiv -1").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --subdiv many").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --rule loop").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --boundary corners").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --offset 0").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --offset -0.5").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --offset nan").status == 2);
  CHECK(nome::test::run_nome_in_process("info " + cube + " --subdiv-after 1").status == 2);
  const std::string dir = nome::test::scratch_dir("budget");
  const auto r = nome::test::run_nome_in_process("export " + cube + " --subdiv 12 -o " + dir + "/huge.obj");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("100663296 faces") && Catch::Contains("--force"));
  CHECK_FALSE(std::filesystem::exists(dir + "/huge.obj"));
  for (const char* cmd : {"info", "export"}) {
    const auto help = nome::test::run_nome_in_process(std::string(cmd) + " --help");
    for (const char* option :
         {"--subdiv N", "--rule RULE", "--boundary MODE", "--offset D", "--subdiv-after M", "--force"})
      CHECK_THAT(help.out, Catch::Contains(option));
  }
}

TEST_CASE("the offset warns about degenerate faces by name", "[app]") {
  const std::string dir = nome::test::scratch_dir("degenerate");
  std::ofstream(dir + "/flat.obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 0 0\nv 2 0 0\n"
                                      "f 1 2 5 4\nf 2 3 6 5\n";
  const auto r = run_nome("info " + dir + "/flat.obj --offset 0.1");
  CHECK(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("nome: warning: offset: 1 degenerate faces") && Catch::Contains("f1"));
}
