#pragma once

#include <string>

#include "nome/scene/scene.hpp"

namespace nome::cli {

// The scene's slider banks (value, range, step) and its top-level instances, as text for people.
std::string scene_text(const scene::Scene& scene);
// The same as one JSON object: {"file", "banks": [{"name", "parameters": [...]}], "instances": [...]}.
std::string scene_json(const scene::Scene& scene);

}  // namespace nome::cli
