#pragma once

#include <string>
#include <vector>

#include "nome/edit/document.hpp"
#include "nome/scene/scene.hpp"

namespace nome {

// The editing model over a parametric scene: the scene evaluated without its editing data is the
// document's geometry; the consolidated mesh and the deletions live in the document (with undo) and go
// back into the scene for saving. Sliders re-evaluate the scene and the edits follow by name.
class SceneDocument {
 public:
  // Takes over the scene's consolidated faces and deletions (as read from a saved .nome file).
  explicit SceneDocument(scene::Scene scene);

  const scene::Scene& scene() const { return scene_; }
  Document& edits() { return document_; }
  const Document& edits() const { return document_; }

  // Moves a slider (see Scene::set_parameter) and resolves the edits again; returns the top-level
  // instances whose geometry changed.
  std::vector<Index> set_parameter(Index parameter, double value);

  // The scene carrying the document's consolidated mesh and deletions, for scene::write_nome. Edits
  // whose vertices or faces are gone at the current slider values cannot be written: they are listed in
  // `left_out` (face names).
  scene::Scene scene_for_saving(std::vector<std::string>* left_out = nullptr) const;

 private:
  scene::Scene scene_;
  Document document_;
};

}  // namespace nome
