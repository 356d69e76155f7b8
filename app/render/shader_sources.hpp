#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace nome::render {

struct ShaderSource {
  std::string text;
  std::string origin;  // the file it came from, or "embedded"
};

// Where shader files are looked for, in order: $NOME_SHADERS, shaders/ beside the executable, the
// install path (../share/nome/shaders from the executable), the source tree the binary was built from.
std::vector<std::filesystem::path> shader_search_path();

// The text of shader file `name` (e.g. "mesh.frag") from the first folder that has it, else the copy
// compiled into the binary. Throws InvalidInputError for a name that exists nowhere.
ShaderSource find_shader_source(const std::string& name, const std::vector<std::filesystem::path>& folders);

}  // namespace nome::render
