#include "viewer/session.hpp"

#include "nome/error.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"

namespace nome::viewer {
namespace {

std::string name_of(const std::vector<std::string>& names, Index i, const char* kind) {
  if (i >= names.size() || names[i].empty())
    throw InvalidInputError(std::string("the displayed ") + kind + " " + std::to_string(i) + " has no name");
  return names[i];
}

}  // namespace

Session Session::open(const std::filesystem::path& path) {
  Session session;
  session.path_ = path;
  session.document_ = is_scene_file(path) ? SceneDocument::from_scene(read_scene(path))
                                          : SceneDocument::from_polygons(read_polygons(path));
  session.update_input();
  return session;
}

Session Session::restore(const std::filesystem::path& document, const std::filesystem::path& recovery) {
  Session session = open(recovery);
  session.path_ = document;
  session.is_modified_ = true;
  return session;
}

void Session::update_input() {
  input_ = document_.pipeline_input();
  parts_ = document_.face_parts(input_);
  ++version_;
}

EditOutcome Session::changed(EditOutcome outcome) {
  if (outcome.applied) {
    is_modified_ = true;
    ++accepted_edits_;
    update_input();
  }
  return outcome;
}

EditOutcome Session::add_polygon(const Mesh& displayed, std::span<const Index> vertices) {
  std::vector<std::string> names;
  for (Index v : vertices) names.push_back(name_of(displayed.vertex_names(), v, "vertex"));
  return changed(document_.edits().add_polygon(names));
}

EditOutcome Session::accept_temporary() {
  return changed(document_.edits().accept_temporary());
}

EditOutcome Session::clear_temporary() {
  return changed(document_.edits().clear_temporary());
}

EditOutcome Session::delete_faces(const Mesh& displayed, std::span<const Index> faces) {
  std::vector<std::string> names;
  for (Index f : faces) names.push_back(name_of(displayed.face_names(), f, "face"));
  return changed(document_.edits().delete_faces(names));
}

EditOutcome Session::zipper(const Mesh& displayed, const BorderSelection& a, const BorderSelection& b,
                            const ZipperOptions& options) {
  return changed(document_.edits().zipper(displayed, a, b, options));
}

bool Session::undo() {
  const bool is_done = document_.edits().undo();
  if (is_done) changed({true, {}});
  return is_done;
}

bool Session::redo() {
  const bool is_done = document_.edits().redo();
  if (is_done) changed({true, {}});
  return is_done;
}

void Session::set_parameter(Index parameter, double value) {
  if (!scene()) throw InvalidInputError("set: " + path_.filename().string() + " has no sliders");
  document_.set_parameter(parameter, value);
  is_modified_ = true;
  update_input();
}

void Session::set_parameter(const std::string& name, double value) {
  if (!scene()) throw InvalidInputError("set: " + path_.filename().string() + " has no sliders");
  document_.set_parameter(name, value);
  is_modified_ = true;
  update_input();
}

std::vector<std::string> Session::save(const std::filesystem::path& path) {
  std::vector<std::string> left_out = document_.save(path);
  path_ = path;
  is_modified_ = !left_out.empty();
  return left_out;
}

void Session::apply_anom(const std::filesystem::path& path) {
  if (!scene())
    throw InvalidInputError(path.string() + ": an .anom file applies to an open scene, and " +
                            path_.filename().string() + " is not one: open its .nome first");
  document_.apply_anom(read_text_file(path), path.string());
  is_modified_ = true;
  update_input();
}

void Session::reload() {
  if (scene())
    document_.reload(read_scene(path_));
  else
    document_.reload(read_polygons(path_));
  update_input();
}

}  // namespace nome::viewer
