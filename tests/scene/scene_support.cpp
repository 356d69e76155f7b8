#include "scene/scene_support.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/shared_examples.hpp"

namespace nome::test {

std::string assets_dir() {
  return std::string(NOME_SOURCE_DIR) + "/assets/";
}

std::string originals_dir() {
  return shared_examples_dir("original");
}

std::vector<std::string> scene_files() {
  std::vector<std::string> files;
  for (const std::string& dir : {assets_dir(), originals_dir()})
    if (std::filesystem::is_directory(dir))
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".nome" || ext == ".nom") files.push_back(entry.path().string());
      }
  return files;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

scene::Scene load_scene_file(const std::string& path) {
  return scene::Scene::from_text(read_text(path), path);
}

std::vector<std::string> scene_errors(const std::string& text) {
  try {
    scene::Scene::from_text(text, "t.nome");
  } catch (const scene::SceneError& e) {
    std::vector<std::string> out;
    for (const scene::Diagnostic& d : e.diagnostics()) out.push_back(d.to_string());
    return out;
  }
  return {};
}

Vec3 vertex_position(const scene::Scene& s, const std::string& full_name) {
  for (const scene::SceneInstance& i : s.instances()) {
    const auto& names = i.geometry.soup.vertex_names;
    for (size_t v = 0; v < names.size(); ++v)
      if (names[v] == full_name) return i.geometry.soup.positions[v];
  }
  throw InvalidInputError("vertex_position: no vertex " + full_name);
}

}  // namespace nome::test
