#include "viewer/session/session.hpp"

#include <algorithm>
#include <cctype>

#include "nome/error.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/io/sif.hpp"
#include "nome/mesh/input_faces.hpp"

namespace nome::viewer {
namespace {

// The document keeps the file's edits: the scene is evaluated without them, once.
const scene::SceneOptions for_document{.shows_edits = false};

std::string name_of(const std::vector<std::string>& names, Index i, const char* kind) {
  if (i >= names.size() || names[i].empty())
    throw InvalidInputError(std::string("the displayed ") + kind + " " + std::to_string(i) + " has no name");
  return names[i];
}

}  // namespace

Session Session::open(const std::filesystem::path& path, bool pair_sif_triangles) {
  Session session;
  session.path_ = path;
  session.pair_sif_triangles_ = pair_sif_triangles;
  if (is_scene_file(path)) {
    session.text_ = read_text_file(path);
    session.document_ = SceneDocument::from_scene(read_scene_text(session.text_, path, for_document));
  } else {
    session.document_ = SceneDocument::from_polygons(session.read_flat());
  }
  session.update_input();
  return session;
}

bool Session::is_sif() const {
  return lower_extension(path_) == ".sif";
}

PolygonSoup Session::read_flat() const {
  if (!is_sif()) return read_polygons(path_);
  return read_sif(path_, {pair_sif_triangles_, SifOptions{}.max_fold_degrees});
}

Session Session::restore(const std::filesystem::path& document, const std::filesystem::path& recovery) {
  Session session = open(recovery);
  session.path_ = document;
  session.is_modified_ = true;
  return session;
}

void Session::update_input() {
  // A slider that only moved vertices takes their positions alone: no polygons, names or parts again; a
  // colour takes the faces' attributes alone.
  if (!polygons_ || document_.input_topology_version() != topology_version_) {
    auto input = std::make_shared<PipelineInput>(document_.pipeline_input());
    // Every stage's faces then know theirs: picking a face of the smoothed solid finds its statement.
    mark_input_faces(input->soup);
    positions_ = std::make_shared<const Buffer<Vec3>>(input->soup.positions);
    face_attributes_ = std::make_shared<const Attributes>(input->soup.face_attributes);
    parts_ = document_.face_parts(*input);
    polygons_ = std::move(input);
    topology_version_ = document_.input_topology_version();
    attributes_version_ = document_.input_attributes_version();
  } else {
    positions_ = std::make_shared<const Buffer<Vec3>>(document_.pipeline_positions());
    if (document_.input_attributes_version() != attributes_version_) {
      Attributes faces = document_.pipeline_face_attributes();
      mark_input_faces(faces, polygons_->soup.num_faces());
      face_attributes_ = std::make_shared<const Attributes>(std::move(faces));
      attributes_version_ = document_.input_attributes_version();
    }
  }
  ++version_;
}

PipelineInput Session::pipeline_input() const {
  PipelineInput input = *polygons_;
  input.soup.positions = *positions_;
  input.soup.face_attributes = *face_attributes_;
  return input;
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

EditOutcome Session::add_polygon(const std::vector<std::string>& vertex_names) {
  return changed(document_.edits().add_polygon(vertex_names));
}

EditOutcome Session::zip_chains(const std::vector<std::string>& a, const std::vector<std::string>& b,
                                const ZipperOptions& options) {
  return changed(document_.edits().zip_chains(a, b, options));
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

EditOutcome Session::set_sharp(const Mesh& displayed, std::span<const Index> edges, float weight) {
  std::vector<std::pair<std::string, std::string>> names;
  for (Index e : edges) {
    const auto [u, w] = displayed.edge(e).vertices;
    names.emplace_back(name_of(displayed.vertex_names(), u, "vertex"),
                       name_of(displayed.vertex_names(), w, "vertex"));
  }
  return changed(document_.edits().set_sharp(names, weight));
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

void Session::set_parameter(scene::ParameterId parameter, double value) {
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

void Session::set_instance_color(const std::string& path, Color color) {
  document_.set_instance_color(path, color);
  is_modified_ = true;
  update_input();
}

void Session::set_instance_surface(const std::string& path, const std::optional<std::string>& surface) {
  document_.set_instance_surface(path, surface);
  is_modified_ = true;
  update_input();
}

void Session::set_print_setup(std::optional<PrintPlacementOptions> setup) {
  document_.set_print_setup(setup);
  is_modified_ = true;
}

void Session::save(const std::filesystem::path& path) {
  document_.save_all(path);
  path_ = path;
  is_modified_ = false;
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
  if (scene()) return reload_text(read_text_file(path_));
  document_.reload(read_flat());
  update_input();
}

void Session::reload_text(std::string_view text) {
  if (!scene())
    throw InvalidInputError(path_.filename().string() + " is not a scene: its text is not evaluated");
  document_.reload(read_scene_text(text, path_, for_document));
  text_ = text;
  update_input();
}

void Session::apply_drag_step(const std::string& text,
                              const std::vector<std::pair<scene::ParameterId, double>>& sliders) {
  bool is_changed = text != text_;
  if (is_changed) reload_text(text);
  for (const auto& [parameter, value] : sliders)
    if (scene()->parameters()[parameter].value != value) {
      document_.set_parameter(parameter, value);
      is_changed = true;
    }
  if (!is_changed) return;
  is_modified_ = true;
  update_input();
}

}  // namespace nome::viewer
