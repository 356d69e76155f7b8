#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "nome/scene/scene.hpp"

namespace nome {

// Reads a scene file by its extension: .nome or .nom (the scene language) or .slf (the SLIDE subset).
// Throws SceneError listing every located error, IoError when the file cannot be read, BudgetError when
// its instances exceed the budget of `options`.
scene::Scene read_scene(const std::filesystem::path& path, const scene::SceneOptions& options = {});
// The same for a text that is (or will be) the content of `path`: an editor's unsaved text, evaluated as the
// file would be (its extension picks the reader, errors are located in it, includes resolve beside it).
scene::Scene read_scene_text(std::string_view text, const std::filesystem::path& path,
                             const scene::SceneOptions& options = {});

// True for the extensions read_scene reads.
bool is_scene_file(const std::filesystem::path& path);
// True for an .anom file: saved slider values and a working mesh that apply to an open scene
// (scene::Scene::apply_anom), never a scene of its own.
bool is_anom_file(const std::filesystem::path& path);

// The whole file as text; IoError when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace nome
