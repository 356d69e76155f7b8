#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nome/edit/scene_document.hpp"
#include "nome/ops/zipper.hpp"

namespace nome::viewer {

// The session's pipeline input as a job takes it, shared rather than copied: the polygons of the latest
// topology (their positions as they were when it was made) and the current positions, with the
// version of that topology (SceneDocument::input_topology_version): a job whose version the pipeline has
// already seen moves the vertices and looks at no polygon.
struct SceneInput {
  std::shared_ptr<const PipelineInput> polygons;
  std::shared_ptr<const Buffer<Vec3>> positions;
  std::uint64_t topology_version = 0;
  // The faces' current attributes (a colour changed since the polygons were made: the same topology).
  std::shared_ptr<const Attributes> face_attributes;
};

// The file open in a window: the kernel's SceneDocument (the scene or flat geometry and its edits) plus
// what only a window needs: the path, whether there are unsaved changes, and the pipeline input of the
// current state. Edits arrive as the displayed mesh's element ids and go to the document by name
// (hierarchical names; `v12`, `f3` for flat files).
class Session {
 public:
  // Reads a scene (.nome .nom .slf) or flat geometry (.obj .stl .sif; a .sif file's triangles paired
  // into quads when `pair_sif_triangles`, report 7.1). Throws nome::Error (a SceneError lists every
  // `file:line:col: message`) when it cannot.
  static Session open(const std::filesystem::path& path, bool pair_sif_triangles = false);
  // The state a crashed viewer left in a recovery file (a saved scene, see Autosave), as unsaved changes
  // to `document`: saving writes the document.
  static Session restore(const std::filesystem::path& document, const std::filesystem::path& recovery);

  const std::filesystem::path& path() const { return path_; }
  bool is_sif() const;
  bool are_sif_triangles_paired() const { return pair_sif_triangles_; }
  // What the scene stage shows: the scene without its deleted faces, then the consolidated and the
  // temporary faces (face_parts() says how many of each).
  // A copy, with the current positions.
  PipelineInput pipeline_input() const;
  SceneInput scene_input() const { return {polygons_, positions_, topology_version_, face_attributes_}; }
  // The polygons, names and parts of pipeline_input() without copying them; their positions may be
  // older than positions().
  const PolygonSoup& polygons() const { return polygons_->soup; }
  const Buffer<Vec3>& positions() const { return *positions_; }
  const FaceParts& face_parts() const { return parts_; }
  // Changes whenever pipeline_input() does.
  std::uint64_t version() const { return version_; }
  // Grows when the polygons change, not when a slider only moves their vertices.
  std::uint64_t topology_version() const { return topology_version_; }
  // Grows when the faces' attributes (colours) change, also with a new topology.
  std::uint64_t attributes_version() const { return attributes_version_; }
  // Unsaved changes (edits since the last save or load).
  bool is_modified() const { return is_modified_; }
  // How many edits (undo and redo included) have been accepted since the session began.
  std::uint64_t accepted_edits() const { return accepted_edits_; }
  const Document& document() const { return document_.edits(); }
  // The scene of a scene file; none for flat geometry (no sliders, no .nome saving).
  const scene::Scene* scene() const { return document_.scene(); }

  // Moves a slider and re-evaluates what reads it. Throws InvalidInputError outside the slider's range
  // or for an unknown name (naming close ones), SceneError when the scene cannot be evaluated with the
  // value (nothing changes then).
  void set_parameter(scene::ParameterId parameter, double value);
  void set_parameter(const std::string& name, double value);
  // The print preparation saved with the scene, an unsaved change. Throws InvalidInputError for flat
  // geometry.
  void set_print_setup(std::optional<PrintPlacementOptions> setup);

  // Gives the instance (a placement path) a colour or names its surface again (undo); throws
  // InvalidInputError for flat geometry or an unknown instance.
  void set_instance_color(const std::string& path, Color color);
  void set_instance_surface(const std::string& path, const std::optional<std::string>& surface);

  // Saves the scene with its slider values and the consolidated faces and deletions as .nome
  // (atomically); the saved file becomes the session's file. Temporary faces are not saved. While an
  // accepted edit's vertices or face are gone at the current slider values the file could not hold it:
  // saving is refused (InvalidInputError naming those edits), nothing is written and the edits stay.
  void save(const std::filesystem::path& path);
  // Writes the scene as save() does, atomically, to another file that does not become the session's (a
  // recovery file), leaving out any edits save() would refuse for. Throws InvalidInputError for flat
  // geometry.
  void write_copy(const std::filesystem::path& path) const { document_.save(path); }

  // Edits of report 7.3.3, on vertices and faces of `displayed` (the scene or merged stage). Each returns
  // what happened; a refused edit changes nothing.
  EditOutcome add_polygon(const Mesh& displayed, std::span<const Index> vertices);
  // The same by the vertices' names (rim vertices have no id in the displayed mesh).
  EditOutcome add_polygon(const std::vector<std::string>& vertex_names);
  EditOutcome accept_temporary();
  EditOutcome clear_temporary();
  EditOutcome delete_faces(const Mesh& displayed, std::span<const Index> faces);
  EditOutcome zipper(const Mesh& displayed, const BorderSelection& a, const BorderSelection& b,
                     const ZipperOptions& options);
  // Zips chains of named vertices: rim lines (report 6.3) or borders, in any mix (Document::zip_chains).
  EditOutcome zip_chains(const std::vector<std::string>& a, const std::vector<std::string>& b,
                         const ZipperOptions& options);
  // Gives the edges of `displayed` a crease weight (0: smooth), by their vertices' names.
  EditOutcome set_sharp(const Mesh& displayed, std::span<const Index> edges, float weight);
  bool undo();
  bool redo();

  // Applies an .anom file (the original program's saved work: slider values and a working mesh that
  // replaces the consolidated faces) to the open scene, as unsaved changes. Throws InvalidInputError for
  // flat geometry, SceneError (nothing changes then) when its names or values do not fit the scene.
  void apply_anom(const std::filesystem::path& path);

  // Reads the file again, keeping the edits; on an error the session keeps what it had and rethrows.
  void reload();
  // The same with `text` as the file's content (the text pane's Apply): one evaluation for both. Throws
  // InvalidInputError for flat geometry.
  void reload_text(std::string_view text);
  // The text the scene was read from: the file's, or the last one reload_text applied; empty for flat
  // geometry.
  const std::string& text() const { return text_; }
  // A drag's step (sculpting by hand): `text` read as the file's content when it differs from text() (the
  // vertices alone move while the faces stay), then the sliders moved. Throws as reload_text and
  // set_parameter do; an unsaved change.
  void apply_drag_step(const std::string& text,
                       const std::vector<std::pair<scene::ParameterId, double>>& sliders);

 private:
  EditOutcome changed(EditOutcome outcome);
  void update_input();

  PolygonSoup read_flat() const;

  std::filesystem::path path_;
  std::string text_;
  bool pair_sif_triangles_ = false;
  SceneDocument document_;
  std::shared_ptr<const PipelineInput> polygons_;
  std::shared_ptr<const Buffer<Vec3>> positions_;
  std::shared_ptr<const Attributes> face_attributes_;
  std::uint64_t topology_version_ = 0, attributes_version_ = 0;
  FaceParts parts_;
  std::uint64_t version_ = 0;
  bool is_modified_ = false;
  std::uint64_t accepted_edits_ = 0;
};

}  // namespace nome::viewer
