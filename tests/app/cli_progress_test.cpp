#include <catch2/catch.hpp>

#include <filesystem>

#include "app/cli_support.hpp"

using nome::test::assets;

namespace {
// Runs nome with a pseudo-terminal for its standard streams (what a person at a terminal gives it).
nome::test::CommandResult run_in_terminal(const std::string& arguments) {
  return nome::test::run_nome_prefixed("python3 -c 'import pty, sys; pty.spawn(sys.argv[1:])'", arguments);
}

}  // namespace

TEST_CASE("long exports show progress in a terminal and nothing extra in a pipe", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("progress");
  // 288 quads subdivided 5 times and thickened: 1.2 million triangles, seconds of work.
  const std::string work = "export " + assets + "torus.obj --subdiv 5 --offset 0.01 --no-check -o " + dir;
  const auto terminal = run_in_terminal(work + "/a.stl");
  REQUIRE(terminal.status == 0);
  CHECK_THAT(terminal.out, Catch::Contains("%") && Catch::Contains("\r\033[K"));
  CHECK_THAT(terminal.out, Catch::Contains("writing STL") || Catch::Contains("subdivision"));
  const auto quiet = run_in_terminal(work + "/b.stl --quiet");
  CHECK_THAT(quiet.out, !Catch::Contains("%"));
  const auto piped = nome::test::run_nome(work + "/c.stl");
  CHECK(piped.status == 0);
  CHECK(piped.err == "nome: wrote " + dir + "/c.stl (589824 vertices, 589824 faces)\n");
  std::filesystem::remove_all(dir);
}
