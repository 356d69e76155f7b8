#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "app/cli_support.hpp"
#include "nome/error.hpp"
#include "render/embedded_shaders.hpp"
#include "render/shader_sources.hpp"

using namespace nome;

TEST_CASE("every shader in shaders/ is compiled in, byte for byte", "[render]") {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(NOME_SOURCE_DIR) + "/shaders")) {
    ++files;
    std::ostringstream text;
    text << std::ifstream(entry.path(), std::ios::binary).rdbuf();
    const render::ShaderSource embedded = render::find_shader_source(entry.path().filename().string(), {});
    CHECK(embedded.origin == "embedded");
    CHECK(embedded.text == text.str());
  }
  CHECK(files >= 7);
  CHECK(render::embedded_shaders().size() == files);
}

TEST_CASE("shader files are looked for in order, the embedded copy last", "[render]") {
  const std::string first = test::scratch_dir("shaders_first"), second = test::scratch_dir("shaders_second");
  std::ofstream(second + "/mesh.vert") << "// second";
  CHECK(render::find_shader_source("mesh.vert", {first, second}).text == "// second");
  std::ofstream(first + "/mesh.vert") << "// first";
  CHECK(render::find_shader_source("mesh.vert", {first, second}).origin == first + "/mesh.vert");
  CHECK_THROWS_AS(render::find_shader_source("missing.frag", {first}), InvalidInputError);
  CHECK(render::shader_folder_in_use({second, first}) == second);
  CHECK(render::shader_folder_in_use({}) == "embedded");
  const auto path = render::shader_search_path();
  REQUIRE(!path.empty());
  CHECK(path.back() == std::filesystem::path(std::string(NOME_SOURCE_DIR) + "/shaders"));
}
