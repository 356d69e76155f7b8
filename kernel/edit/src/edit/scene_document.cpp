#include "nome/edit/scene_document.hpp"

#include <algorithm>

#include "nome/error.hpp"
#include "nome/scene/save_nome.hpp"

namespace nome {

SceneDocument SceneDocument::from_scene(scene::Scene scene) {
  SceneDocument doc;
  doc.set_scene(std::move(scene));
  return doc;
}

SceneDocument SceneDocument::from_polygons(PolygonSoup soup) {
  if (soup.vertex_names.empty())
    for (Index v = 0; v < soup.num_vertices(); ++v) soup.vertex_names.push_back("v" + std::to_string(v + 1));
  if (soup.face_names.empty())
    for (Index f = 0; f < soup.num_faces(); ++f) soup.face_names.push_back("f" + std::to_string(f + 1));
  SceneDocument doc;
  doc.document_ = Document(std::move(soup));
  return doc;
}

void SceneDocument::set_scene(scene::Scene scene) {
  scene::SceneEdits edits = scene.take_edits();
  scene_.emplace(std::move(scene));
  document_.set_scene_geometry(scene_->combined_soup());
  document_.load_edits(edits.consolidated, std::move(edits.deleted), std::move(edits.sharp));
}

void SceneDocument::set_print_setup(std::optional<PrintPlacementOptions> setup) {
  if (!scene_)
    throw InvalidInputError("print setup: only scene files keep one (export applies it to others)");
  scene_->set_print_setup(setup);
}

std::vector<scene::InstanceId> SceneDocument::set_parameter(scene::ParameterId parameter, double value) {
  if (!scene_) throw InvalidInputError("set: flat geometry has no sliders");
  std::vector<scene::InstanceId> changed = scene_->set_parameter(parameter, value);
  follow_scene_change();
  return changed;
}

std::vector<scene::InstanceId> SceneDocument::set_clock(const std::string& name, double value) {
  if (!scene_) throw InvalidInputError("set " + name + ": flat geometry has no clock");
  std::vector<scene::InstanceId> changed = scene_->set_clock(name, value);
  follow_scene_change();
  return changed;
}

void SceneDocument::follow_scene_change() {
  if (scene_->last_change_moved_vertices_only())
    document_.move_scene_vertices(scene_->combined_positions());
  else
    document_.set_scene_geometry(scene_->combined_soup());
}

std::vector<scene::InstanceId> SceneDocument::set_parameter(const std::string& name, double value) {
  if (!scene_) throw InvalidInputError("set: flat geometry has no sliders");
  const auto id = scene_->find_parameter(name);
  if (!id) {
    std::vector<std::string> known;
    for (const scene::Parameter& p : scene_->parameters()) known.push_back(p.full_name);
    throw InvalidInputError("set: no slider '" + name + "'" + scene::did_you_mean(name, known));
  }
  return set_parameter(*id, value);
}

void SceneDocument::set_instance_color(const std::string& path, Color color) {
  if (!scene_) throw InvalidInputError("colour: flat geometry has no instances");
  scene_->set_instance_color(path, color);
  document_.set_scene_face_attributes(scene_->combined_face_attributes());
}

void SceneDocument::set_instance_surface(const std::string& path, const std::optional<std::string>& surface) {
  if (!scene_) throw InvalidInputError("colour: flat geometry has no instances");
  scene_->set_instance_surface(path, surface);
  document_.set_scene_face_attributes(scene_->combined_face_attributes());
}

void SceneDocument::apply_anom(std::string_view text, const std::string& file) {
  if (!scene_)
    throw InvalidInputError(file + ": an .anom file applies to an open scene: open its .nome first");
  // The .anom's working mesh replaces the consolidated faces; the deletions stay. The scene, evaluated
  // again with the .anom's slider values, resolves the working mesh and hands it over.
  scene_->apply_anom(text, file);
  const scene::SceneEdits working = scene_->take_edits();
  document_.set_scene_geometry(scene_->combined_soup());
  document_.load_edits(working.consolidated, document_.deleted_faces(), document_.sharp_edges());
}

void SceneDocument::reload(scene::Scene fresh) {
  // The file's own edits are those the document holds already.
  fresh.take_edits();
  if (scene_) {
    // The values the user moved sliders to survive an edit of the text (where the slider is still there
    // and in range); a slider left at the file's value takes the file's new one.
    for (const scene::Parameter& p : scene_->parameters()) {
      const auto id = fresh.find_parameter(p.full_name);
      if (!id || p.value == p.file_value) continue;
      const scene::Parameter& q = fresh.parameters()[*id];
      if (p.value != q.value && p.value >= q.min && p.value <= q.max) fresh.set_parameter(*id, p.value);
    }
  }
  scene_.emplace(std::move(fresh));
  document_.update_scene_geometry(scene_->combined_soup());
}

void SceneDocument::reload(PolygonSoup polygons) {
  document_.set_scene_geometry(from_polygons(std::move(polygons)).document_.scene_geometry());
}

FaceParts SceneDocument::face_parts(const PipelineInput& input) const {
  FaceParts parts;
  Index* counts[] = {&parts.scene, &parts.consolidated, &parts.temporary};
  for (size_t i = 0; i < input.parts.size() && i < 3; ++i) *counts[i] = input.parts[i].faces;
  return parts;
}

scene::SceneEdits SceneDocument::saved_edits(std::vector<std::string>* left_out) const {
  if (!scene_)
    throw InvalidInputError("save: only scene files are saved as .nome (export writes .obj and .stl)");
  std::vector<std::string> unresolved, skipped;
  for (const UnresolvedEdit& edit : document_.unresolved()) unresolved.push_back(edit.face);
  auto keep = [&](const std::string& name) {
    const bool is_gone = std::find(unresolved.begin(), unresolved.end(), name) != unresolved.end();
    if (is_gone) skipped.push_back(name);
    return !is_gone;
  };
  scene::SceneEdits edits;
  for (const EditedFace& face : document_.consolidated_faces())
    if (keep(face.name)) edits.consolidated.push_back(face.vertices);
  for (const std::string& name : document_.deleted_faces())
    if (keep(name)) edits.deleted.push_back(name);
  for (const NamedSharpEdge& e : document_.sharp_edges())
    if (keep("sharp (" + e.a + ", " + e.b + ")")) edits.sharp.push_back(e);
  if (left_out) *left_out = std::move(skipped);
  return edits;
}

std::string SceneDocument::saved_text(std::vector<std::string>* left_out) const {
  const scene::SceneEdits edits = saved_edits(left_out);
  return scene::to_nome_text(*scene_, edits);
}

void SceneDocument::save_all(const std::filesystem::path& path) const {
  std::vector<std::string> left_out;
  const scene::SceneEdits edits = saved_edits(&left_out);
  if (!left_out.empty()) {
    std::string names;
    for (const std::string& name : left_out) names += (names.empty() ? "" : ", ") + name;
    throw InvalidInputError("save: refused, the file would lose " + std::to_string(left_out.size()) +
                            " edits whose vertices or faces are gone at the current slider values (" + names +
                            "): move the sliders back until they show, or delete them, then save");
  }
  scene::write_nome(*scene_, edits, path);
}

std::vector<std::string> SceneDocument::save(const std::filesystem::path& path) const {
  std::vector<std::string> left_out;
  const scene::SceneEdits edits = saved_edits(&left_out);
  scene::write_nome(*scene_, edits, path);
  return left_out;
}

}  // namespace nome
