#include "render/shader_sources.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include "nome/error.hpp"
#include "render/embedded_shaders.hpp"

namespace nome::render {

std::vector<std::filesystem::path> shader_search_path() {
  std::vector<std::filesystem::path> folders;
  if (const char* env = std::getenv("NOME_SHADERS"); env && *env) folders.emplace_back(env);
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    folders.push_back(executable.parent_path() / "shaders");
    folders.push_back((executable.parent_path() / NOME_INSTALLED_SHADER_DIR).lexically_normal());
  }
  folders.emplace_back(NOME_SHADER_DIR);
  return folders;
}

ShaderSource find_shader_source(const std::string& name, const std::vector<std::filesystem::path>& folders) {
  for (const auto& folder : folders) {
    const auto path = folder / name;
    std::ifstream in(path, std::ios::binary);
    if (!in) continue;
    std::ostringstream text;
    text << in.rdbuf();
    return {text.str(), path.string()};
  }
  for (const EmbeddedShader& shader : embedded_shaders())
    if (shader.name == name) return {std::string(shader.text), "embedded"};
  throw InvalidInputError("find_shader_source: no shader named '" + name + "'");
}

std::string shader_folder_in_use(const std::vector<std::filesystem::path>& folders) {
  const ShaderSource source = find_shader_source("mesh.vert", folders);
  return source.origin == "embedded" ? source.origin
                                     : std::filesystem::path(source.origin).parent_path().string();
}

}  // namespace nome::render
