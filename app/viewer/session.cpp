#include "viewer/session.hpp"

#include <algorithm>

#include "nome/error.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/concatenate.hpp"
#include "nome/scene/save_nome.hpp"

namespace nome::viewer {
namespace {

// Edits refer to vertices and faces by name; flat files get the names their lines give them.
PolygonSoup with_names(PolygonSoup soup) {
  if (soup.vertex_names.empty())
    for (Index v = 0; v < soup.num_vertices(); ++v) soup.vertex_names.push_back("v" + std::to_string(v + 1));
  if (soup.face_names.empty())
    for (Index f = 0; f < soup.num_faces(); ++f) soup.face_names.push_back("f" + std::to_string(f + 1));
  return soup;
}

std::string name_of(const std::vector<std::string>& names, Index i, const char* kind) {
  if (i >= names.size() || names[i].empty())
    throw InvalidInputError(std::string("the displayed ") + kind + " " + std::to_string(i) + " has no name");
  return names[i];
}

}  // namespace

Session Session::open(const std::filesystem::path& path) {
  Session session;
  session.path_ = path;
  if (is_scene_file(path)) {
    session.scene_.emplace(read_scene(path));
    session.document_ = Document(session.scene_->combined_soup());
  } else {
    session.document_ = Document(with_names(read_polygons(path)));
  }
  session.update_soup();
  return session;
}

Session Session::restore(const std::filesystem::path& document, const std::filesystem::path& recovery) {
  Session session = open(recovery);
  session.path_ = document;
  session.is_modified_ = true;
  return session;
}

void Session::update_soup() {
  std::vector<Mesh> parts;
  GluedFaces scene = document_.scene_mesh(), consolidated = document_.consolidated_mesh(),
             temporary = document_.temporary_mesh();
  parts_ = {scene.mesh.num_faces(), consolidated.mesh.num_faces(), temporary.mesh.num_faces()};
  parts.push_back(std::move(scene.mesh));
  parts.push_back(std::move(consolidated.mesh));
  parts.push_back(std::move(temporary.mesh));
  soup_ = concatenate(parts);
  ++version_;
}

EditOutcome Session::changed(EditOutcome outcome) {
  if (outcome.applied) {
    is_modified_ = true;
    ++accepted_edits_;
    update_soup();
  }
  return outcome;
}

EditOutcome Session::add_polygon(const Mesh& displayed, std::span<const Index> vertices) {
  std::vector<std::string> names;
  for (Index v : vertices) names.push_back(name_of(displayed.vertex_names(), v, "vertex"));
  return changed(document_.add_polygon(names));
}

EditOutcome Session::accept_temporary() {
  return changed(document_.accept_temporary());
}

EditOutcome Session::clear_temporary() {
  return changed(document_.clear_temporary());
}

EditOutcome Session::delete_faces(const Mesh& displayed, std::span<const Index> faces) {
  std::vector<std::string> names;
  for (Index f : faces) names.push_back(name_of(displayed.face_names(), f, "face"));
  return changed(document_.delete_faces(names));
}

EditOutcome Session::zipper(const Mesh& displayed, const BorderSelection& a, const BorderSelection& b,
                            const ZipperOptions& options) {
  return changed(document_.zipper(displayed, a, b, options));
}

bool Session::undo() {
  const bool is_done = document_.undo();
  if (is_done) changed({true, {}});
  return is_done;
}

bool Session::redo() {
  const bool is_done = document_.redo();
  if (is_done) changed({true, {}});
  return is_done;
}

void Session::set_parameter(Index parameter, double value) {
  if (!scene_) throw InvalidInputError("set: " + path_.filename().string() + " has no sliders");
  scene_->set_parameter(parameter, value);
  document_.set_scene_geometry(scene_->combined_soup());
  is_modified_ = true;
  update_soup();
}

void Session::set_parameter(const std::string& name, double value) {
  if (!scene_) throw InvalidInputError("set: " + path_.filename().string() + " has no sliders");
  const auto id = scene_->find_parameter(name);
  if (!id) {
    std::vector<std::string> known;
    for (const scene::Parameter& p : scene_->parameters()) known.push_back(p.full_name);
    throw InvalidInputError("set: no slider '" + name + "'" + scene::did_you_mean(name, known));
  }
  set_parameter(*id, value);
}

scene::Scene Session::saved_scene() const {
  if (!scene_)
    throw InvalidInputError("save: only scene files are saved as .nome (export writes .obj and .stl)");
  // The file's own consolidated faces and deletions, then this session's.
  std::vector<std::vector<std::string>> consolidated = scene_->consolidated_faces();
  for (const EditedFace& face : document_.consolidated_faces()) consolidated.push_back(face.vertices);
  std::vector<std::string> deleted = scene_->deleted_faces();
  for (const std::string& name : document_.deleted_faces())
    if (std::find(deleted.begin(), deleted.end(), name) == deleted.end()) deleted.push_back(name);
  scene::Scene saved = *scene_;
  saved.set_consolidated_faces(std::move(consolidated));
  saved.set_deleted_faces(std::move(deleted));
  return saved;
}

void Session::save(const std::filesystem::path& path) {
  scene::Scene saved = saved_scene();
  scene::write_nome(saved, path);
  // The saved file now holds the accepted edits: start from it, keeping the temporary faces' intent lost
  // only when the user had not accepted them (as the report's program did).
  scene_.emplace(std::move(saved));
  document_ = Document(scene_->combined_soup());
  path_ = path;
  is_modified_ = false;
  update_soup();
}

void Session::apply_anom(const std::filesystem::path& path) {
  if (!scene_)
    throw InvalidInputError(path.string() + ": an .anom file applies to an open scene, and " +
                            path_.filename().string() + " is not one: open its .nome first");
  scene::Scene next = *scene_;
  next.apply_anom(read_text_file(path), path.string());
  scene_.emplace(std::move(next));
  document_.set_scene_geometry(scene_->combined_soup());
  is_modified_ = true;
  update_soup();
}

void Session::reload() {
  if (!scene_) {
    document_.set_scene_geometry(with_names(read_polygons(path_)));
    update_soup();
    return;
  }
  scene::Scene fresh = read_scene(path_);
  // The user's slider values survive an edit of the text (where the slider is still there and in range).
  for (const scene::Parameter& p : scene_->parameters()) {
    const auto id = fresh.find_parameter(p.full_name);
    if (!id) continue;
    const scene::Parameter& q = fresh.parameters()[*id];
    if (p.value != q.value && p.value >= q.min && p.value <= q.max) fresh.set_parameter(*id, p.value);
  }
  scene_.emplace(std::move(fresh));
  document_.set_scene_geometry(scene_->combined_soup());
  update_soup();
}

}  // namespace nome::viewer
