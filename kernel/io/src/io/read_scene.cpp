#include "nome/io/read_scene.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "nome/error.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/slide/read_slf.hpp"

namespace nome {
std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool is_scene_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".nome" || ext == ".nom" || ext == ".slf";
}

bool is_anom_file(const std::filesystem::path& path) {
  return lower_extension(path) == ".anom";
}

scene::Scene read_scene(const std::filesystem::path& path, const scene::SceneOptions& options) {
  return read_scene_text(read_text_file(path), path, options);
}

scene::Scene read_scene_text(std::string_view text, const std::filesystem::path& path,
                             const scene::SceneOptions& options) {
  if (lower_extension(path) != ".slf") return scene::Scene::from_text(text, path.string(), options);
  return slide::read_slf_scene(text, path, options, {},
                               [](const std::filesystem::path& file) { return read_polygons(file); });
}

}  // namespace nome
