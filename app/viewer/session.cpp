#include "viewer/session.hpp"

#include "nome/error.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/mesh/concatenate.hpp"

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
  session.document_ = Document(with_names(read_polygons(path)));
  session.update_soup();
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

void Session::reload() {
  document_.set_scene_geometry(with_names(read_polygons(path_)));
  update_soup();
}

}  // namespace nome::viewer
