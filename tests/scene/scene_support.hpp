#pragma once

#include <string>
#include <vector>

#include "nome/scene/scene.hpp"

namespace nome::test {

// assets/ (the report's examples and ours) and the shared examples' original/ folder (files of the original
// programs, written by others: tests that read them need NOME_NEEDS_SHARED_EXAMPLES).
std::string assets_dir();
std::string originals_dir();
// Every .nome and .nom file of assets/ and (where present) the original program's examples.
std::vector<std::string> scene_files();
std::string read_text(const std::string& path);
scene::Scene load_scene_file(const std::string& path);

// Every error the text produces, each as `t.nome:line:col: message`; empty if it loads.
std::vector<std::string> scene_errors(const std::string& text);

// The world position of a vertex of the scene, by its full hierarchical name.
Vec3 vertex_position(const scene::Scene& s, const std::string& full_name);

}  // namespace nome::test
