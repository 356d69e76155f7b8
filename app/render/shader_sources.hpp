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
// install path (share/nome/shaders of the installed tree the executable is in: ../share/nome/shaders from
// bin/ by default), the source tree the binary was built from.
std::vector<std::filesystem::path> shader_search_path();

// The text of shader file `name` (e.g. "mesh.frag") from the first folder that has it, else the copy
// compiled into the binary. Throws InvalidInputError for a name that exists nowhere.
ShaderSource find_shader_source(const std::string& name, const std::vector<std::filesystem::path>& folders);

// The folder the renderer's shaders come from (the first in `folders` holding mesh.vert), or "embedded".
std::string shader_folder_in_use(const std::vector<std::filesystem::path>& folders);

}  // namespace nome::render
