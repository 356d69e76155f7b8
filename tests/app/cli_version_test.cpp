#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>

#include "app/cli_support.hpp"

using namespace nome;

TEST_CASE("nome --version and nome version print the project version and the commit", "[app][version]") {
  const test::CommandResult dashed = test::run_nome("--version");
  REQUIRE(dashed.status == 0);
  // Built from this checkout, so a commit is named.
  CHECK(std::regex_match(dashed.out, std::regex("nome 0\\.1\\.0 \\(git [0-9a-f]{12}(-dirty)?\\)\n")));
  CHECK(test::run_nome("version").out == dashed.out);
  CHECK(test::run_nome("version extra.nome").status == 2);
}

TEST_CASE("nome version --verbose names the GL backend and the shader folder in use", "[app][version]") {
  const test::CommandResult r = test::run_nome_prefixed("env -u NOME_SHADERS", "version --verbose");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("GL backend: EGL") != std::string::npos);
  CHECK(r.out.find("OpenGL") != std::string::npos);
  // A build-tree binary has no installed tree around it: the source tree's shaders are used.
  CHECK(r.out.find("shaders: " + std::string(NOME_SOURCE_DIR) + "/shaders\n") != std::string::npos);
  const test::CommandResult elsewhere =
      test::run_nome_prefixed("env NOME_SHADERS=/nonexistent-nome-shaders", "--version --verbose");
  CHECK(elsewhere.out.find("shaders: " + std::string(NOME_SOURCE_DIR) + "/shaders\n") != std::string::npos);
  const std::string own = test::scratch_dir("version_shaders");
  std::filesystem::copy_file(std::string(NOME_SOURCE_DIR) + "/shaders/mesh.vert", own + "/mesh.vert");
  const test::CommandResult chosen = test::run_nome_prefixed("env NOME_SHADERS=" + own, "version -v");
  CHECK(chosen.out.find("shaders: " + own + "\n") != std::string::npos);
}
