#include <catch2/catch.hpp>

#include <filesystem>

#include "app/cli_support.hpp"

using nome::test::assets;

namespace {
// Runs nome with a pseudo-terminal for its standard streams (what a person at a terminal gives it).
nome::test::CommandResult run_in_terminal(const std::string& arguments) {
  // Bars show at once (not after half a second), whatever the build's speed.
  return nome::test::run_nome_prefixed(
      "env NOME_PROGRESS_AFTER_MS=0 python3 -c 'import pty, sys; pty.spawn(sys.argv[1:])'", arguments);
}

}  // namespace

TEST_CASE("long exports show progress in a terminal and nothing extra in a pipe", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("progress");
  const std::string work = "export " + assets + "torus.obj --subdiv 3 --offset 0.01 --no-check -o " + dir;
  const auto terminal = run_in_terminal(work + "/a.stl");
  REQUIRE(terminal.status == 0);
  CHECK_THAT(terminal.out, Catch::Contains("%") && Catch::Contains("\r\033[K"));
  CHECK_THAT(terminal.out, Catch::Contains("nome: subdivision") && Catch::Contains("nome: offset"));
  const auto quiet = run_in_terminal(work + "/b.stl --quiet");
  CHECK_THAT(quiet.out, !Catch::Contains("%"));
  const auto piped = nome::test::run_nome(work + "/c.stl");
  CHECK(piped.status == 0);
  CHECK(piped.err == "nome: wrote " + dir + "/c.stl (36864 vertices, 36864 faces)\n");
  std::filesystem::remove_all(dir);
}
