#pragma once

#include <filesystem>
#include <string>

#include "nome/scene/scene.hpp"

namespace nome::scene {

// The scene as .nome text (report 7.5): the banks with the sliders' current values, every definition
// and instance, then the edits: the deletions (by full hierarchical name), the consolidated mesh
// (`consolidate` block) and the sharp edges. Reading it back gives the same geometry. Comments and
// layout of the original are not kept. Nothing is evaluated: the text comes from the scene's statements
// and slider values and from `edits` as given.
std::string to_nome_text(const Scene& scene, const SceneEdits& edits);
// With the scene's own edits (Scene::edits).
std::string to_nome_text(const Scene& scene);

// Writes to_nome_text atomically (the old file stays whole if anything fails).
void write_nome(const Scene& scene, const SceneEdits& edits, const std::filesystem::path& path);
void write_nome(const Scene& scene, const std::filesystem::path& path);

}  // namespace nome::scene
