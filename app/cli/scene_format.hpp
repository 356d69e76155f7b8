#pragma once

#include <string>

#include "nome/edit/scene_document.hpp"

namespace nome::cli {

// The scene's slider banks (value, range, step), its top-level instances and the file's edits (the
// consolidated mesh, deleted faces, sharp edges), as text for people.
std::string scene_text(const SceneDocument& document);
// The same as one JSON object: {"file", "banks": [{"name", "parameters": [...]}], "instances": [...],
// "edits": {"consolidated_vertices", "consolidated_faces", "deleted_faces", "sharp_edges"}}.
std::string scene_json(const SceneDocument& document);

}  // namespace nome::cli
