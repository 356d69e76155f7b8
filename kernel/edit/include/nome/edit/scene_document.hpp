#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nome/edit/document.hpp"
#include "nome/ops/pipeline_input.hpp"
#include "nome/scene/scene.hpp"

namespace nome {

// The faces of a document's pipeline input, by kind: the scene's first, then the consolidated, then the
// temporary ones (faces keep this order through the scene and merged stages).
struct FaceParts {
  Index scene = 0;
  Index consolidated = 0;
  Index temporary = 0;
};

// The one model of what a user edits: a parametric scene (or the polygons of a flat file) and the edits
// over it (report 7.3.3: temporary and consolidated faces, deleted faces, sharp edges, undo and redo).
// The edits have one owner, the Document: the consolidated faces, deletions and sharp edges a file holds
// move into it when the scene is taken over, name the scene's vertices and faces, and follow the sliders
// by name; the scene is evaluated without them. Saving writes the scene's statements and slider values and
// the Document's edits as text, copying and evaluating nothing. Edits whose vertices a slider removed are
// kept (unresolved) and come back with them.
class SceneDocument {
 public:
  // Takes over the scene's edits (Scene::take_edits): read with SceneOptions::shows_edits false, the
  // scene is not evaluated again.
  static SceneDocument from_scene(scene::Scene scene);
  // The polygons of a flat file (.obj .stl .sif); unnamed vertices and faces get the names their lines
  // give them (`v12`, `f3`), for the edits to refer to.
  static SceneDocument from_polygons(PolygonSoup polygons);

  // The scene of a scene file; none for flat geometry (no sliders, no .nome saving).
  const scene::Scene* scene() const { return scene_ ? &*scene_ : nullptr; }
  Document& edits() { return document_; }
  const Document& edits() const { return document_; }

  // Moves a slider (by id, or by `bank_name` / `bank.name`) and resolves the edits again; returns the
  // top-level instances whose geometry changed. Throws InvalidInputError outside the slider's range or
  // for an unknown name (naming close ones), SceneError when the scene cannot be evaluated with the value
  // (nothing changes then).
  std::vector<scene::InstanceId> set_parameter(scene::ParameterId parameter, double value);
  std::vector<scene::InstanceId> set_parameter(const std::string& name, double value);
  // Sets the scene's $time or $frame (Scene::set_clock) and resolves the edits again.
  std::vector<scene::InstanceId> set_clock(const std::string& name, double value);
  // The print preparation saved with the scene (Scene::print_setup). Throws InvalidInputError for flat
  // geometry.
  void set_print_setup(std::optional<PrintPlacementOptions> setup);

  // Gives the instance (a placement path, `sh_tun1`) a colour, or names its surface again (an undo),
  // as Scene::set_instance_color and set_instance_surface do; the faces take the colour at once (new face
  // attributes, the same topology). Throws
  // InvalidInputError for flat geometry or an unknown instance.
  void set_instance_color(const std::string& path, Color color);
  void set_instance_surface(const std::string& path, const std::optional<std::string>& surface);

  // Applies an .anom text (the original program's saved slider values and working mesh, which replaces
  // the consolidated faces). Throws InvalidInputError for flat geometry, SceneError (nothing changes)
  // when its names or values do not fit the scene.
  void apply_anom(std::string_view text, const std::string& file);
  // The file read again (best with SceneOptions::shows_edits false), keeping the edits and the values the
  // user moved sliders to (where the slider is still there and its range holds the value; the others take
  // the file's values).
  void reload(scene::Scene fresh);
  void reload(PolygonSoup polygons);

  // The scene stage's polygons for the pipeline: the scene without its deleted faces, the consolidated
  // and the temporary faces (face_parts() says how many of each).
  PipelineInput pipeline_input() const { return document_.pipeline_input(); }
  // What changed since a caller took pipeline_input(): while input_topology_version() stays, only the
  // positions moved, and pipeline_positions() holds them (Document's).
  Buffer<Vec3> pipeline_positions() const { return document_.pipeline_positions(); }
  std::uint64_t input_topology_version() const { return document_.input_topology_version(); }
  // A colour changed: new face attributes for the same polygons (Document's).
  Attributes pipeline_face_attributes() const { return document_.pipeline_face_attributes(); }
  std::uint64_t input_attributes_version() const { return document_.input_attributes_version(); }
  FaceParts face_parts(const PipelineInput& input) const;

  // The edits a saved file holds: the consolidated faces, deletions and sharp edges (the temporary faces,
  // not accepted, are not saved). Edits whose vertices or faces are gone at the current slider values
  // cannot be written: they are listed in `left_out` (face names). Throws InvalidInputError for flat
  // geometry.
  scene::SceneEdits saved_edits(std::vector<std::string>* left_out = nullptr) const;
  // The .nome text of the scene with saved_edits() (scene::to_nome_text).
  std::string saved_text(std::vector<std::string>* left_out = nullptr) const;
  // Writes saved_text, atomically; the edits and their undo history stay as they are. Returns the edits
  // left out.
  std::vector<std::string> save(const std::filesystem::path& path) const;
  // What a user's Save does: writes as save() does, unless an edit would be left out; then nothing is
  // written and InvalidInputError names those edits and what to do.
  void save_all(const std::filesystem::path& path) const;

 private:
  void set_scene(scene::Scene scene);
  // The edits resolved again over the scene's new geometry: its positions alone when only they moved.
  void follow_scene_change();

  std::optional<scene::Scene> scene_;
  Document document_;
};

}  // namespace nome
