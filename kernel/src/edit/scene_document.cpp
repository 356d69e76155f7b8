#include "nome/edit/scene_document.hpp"

#include <algorithm>

namespace nome {

SceneDocument::SceneDocument(scene::Scene scene) : scene_(std::move(scene)) {
  const std::vector<std::vector<std::string>> consolidated = scene_.consolidated_faces();
  std::vector<std::string> deleted = scene_.deleted_faces();
  scene_.set_consolidated_faces({});
  scene_.set_deleted_faces({});
  document_.set_scene_geometry(scene_.combined_soup());
  document_.load_edits(consolidated, std::move(deleted));
}

std::vector<Index> SceneDocument::set_parameter(Index parameter, double value) {
  std::vector<Index> changed = scene_.set_parameter(parameter, value);
  document_.set_scene_geometry(scene_.combined_soup());
  return changed;
}

scene::Scene SceneDocument::scene_for_saving(std::vector<std::string>* left_out) const {
  std::vector<std::string> unresolved, skipped;
  for (const UnresolvedEdit& edit : document_.unresolved()) unresolved.push_back(edit.face);
  auto keep = [&](const std::string& name) {
    const bool is_gone = std::find(unresolved.begin(), unresolved.end(), name) != unresolved.end();
    if (is_gone) skipped.push_back(name);
    return !is_gone;
  };
  std::vector<std::vector<std::string>> consolidated;
  for (const EditedFace& face : document_.consolidated_faces())
    if (keep(face.name)) consolidated.push_back(face.vertices);
  std::vector<std::string> deleted;
  for (const std::string& name : document_.deleted_faces())
    if (keep(name)) deleted.push_back(name);
  if (left_out) *left_out = std::move(skipped);

  scene::Scene out = scene_;
  out.set_consolidated_faces(std::move(consolidated));
  out.set_deleted_faces(std::move(deleted));
  return out;
}

}  // namespace nome
