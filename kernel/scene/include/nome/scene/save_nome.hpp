#pragma once

#include <filesystem>
#include <string>

#include "nome/scene/scene.hpp"

namespace nome::scene {

// The scene as .nome text (report 7.5): the banks with the sliders' current values, every definition
// and instance, the deletions (by full hierarchical name) and the consolidated mesh (`consolidate`
// block). Reading it back gives the same geometry. Comments and layout of the original are not kept.
std::string to_nome_text(const Scene& scene);

// Writes to_nome_text atomically (the old file stays whole if anything fails).
void write_nome(const Scene& scene, const std::filesystem::path& path);

}  // namespace nome::scene
