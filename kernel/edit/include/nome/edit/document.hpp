#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/named_sharp_edge.hpp"
#include "nome/ops/pipeline_input.hpp"
#include "nome/ops/zipper.hpp"

namespace nome {

// A face the user added, its vertices given by hierarchical name so that it follows the scene through
// slider changes.
struct EditedFace {
  std::string name;  // unique within the document: "edit7"
  std::vector<std::string> vertices;
};

// What an edit did: applied, or refused with the reason (nothing changed then).
struct EditOutcome {
  bool applied = false;
  std::string message;
};

// An edit that cannot be shown with the current geometry (a slider lowered a vertex count): it is kept
// and comes back when its vertices do.
struct UnresolvedEdit {
  std::string face;                  // the edited face, or the deleted scene face
  std::vector<std::string> missing;  // the vertex names not found (empty: the scene face is gone)
};

// The editing model of the report (7.3.3) as data, without any window: the scene's evaluated geometry,
// a temporary mesh of added faces, the consolidated mesh they are accepted into, and deleted scene
// faces. Every edit is a small command on an undo stack (the geometry is never copied per step).
class Document {
 public:
  Document() = default;
  // `scene_geometry`: every top-level instance with hierarchically named vertices and faces (as the
  // scene's combined soup gives it).
  explicit Document(PolygonSoup scene_geometry);

  // Replaces the geometry after a slider change. Edits refer to names and are resolved again.
  void set_scene_geometry(PolygonSoup geometry);
  // New geometry for the scene, which may differ from the current one in its positions alone (the scene's
  // text read again after a number changed): then only the positions, the faces' origins and attributes
  // change and the topology version stays; otherwise as set_scene_geometry.
  void update_scene_geometry(PolygonSoup geometry);
  // New positions for the scene's vertices, its faces and names unchanged (a slider that only moved
  // vertices): the name indexes stay. Throws InvalidInputError when the count differs.
  void move_scene_vertices(Buffer<Vec3> positions);
  const PolygonSoup& scene_geometry() const { return scene_; }
  // The consolidated faces (vertex names) and deleted face names read from a saved file; clears the
  // temporary mesh and the undo history.
  void load_edits(const std::vector<std::vector<std::string>>& consolidated, std::vector<std::string> deleted,
                  std::vector<NamedSharpEdge> sharp_edges = {});

  // Adds a polygon through the named vertices, in order, to the temporary mesh. Refused if a vertex is
  // unknown or repeated or an edge already has two faces. Reversed if most of its edges that already
  // have a face would otherwise run the same way as that face (the report's "auto-correct orientation").
  EditOutcome add_polygon(const std::vector<std::string>& vertex_names);
  // Moves the temporary faces into the consolidated mesh.
  EditOutcome accept_temporary();
  EditOutcome clear_temporary();
  // Deletes faces by name: scene faces are recorded as deleted, edited faces removed. Edges and
  // vertices left without faces disappear from the derived meshes.
  EditOutcome delete_faces(const std::vector<std::string>& face_names);
  // Zips two borders of `displayed` (a mesh whose vertex names are scene names, such as a part or the
  // merged mesh) into the temporary mesh.
  EditOutcome zipper(const Mesh& displayed, const BorderSelection& a, const BorderSelection& b,
                     const ZipperOptions& options = {});

  // Zips two chains of named vertices into the temporary mesh: rim lines (report 6.3, vertices no face
  // uses) or borders, in any mix. A whole loop is given from its start with the start repeated at the
  // end; both are loops or both segments. Chain B is taken in the direction that gives the cheaper strip
  // (a loop from the same start). The strip is oriented to agree with the faces already along the chains
  // (either way when there are none).
  EditOutcome zip_chains(const std::vector<std::string>& chain_a, const std::vector<std::string>& chain_b,
                         const ZipperOptions& options = {});

  // Gives the edges between the named vertex pairs a crease weight for subdivision (OpenSubdiv's sharpness:
  // 0 smooth, which unmarks them; infinite_sharpness and up infinitely sharp). Refused when a pair is no
  // edge of the scene's faces, or when the edge is sharp in the scene's own text with another weight (its
  // `sharp` is changed there). Undo gives each edge its weight from before.
  EditOutcome set_sharp(const std::vector<std::pair<std::string, std::string>>& edges, float weight);
  // The edges marked sharp by edits, as vertex-name pairs (the smaller name first) with their weights.
  const std::vector<NamedSharpEdge>& sharp_edges() const { return sharp_; }

  bool can_undo() const { return done_ > 0; }
  bool can_redo() const { return done_ < history_.size(); }
  bool undo();
  bool redo();

  const std::vector<EditedFace>& temporary_faces() const { return temporary_; }
  const std::vector<EditedFace>& consolidated_faces() const { return consolidated_; }
  const std::vector<std::string>& deleted_faces() const { return deleted_; }
  std::vector<UnresolvedEdit> unresolved() const;

  // Derived polygons: the scene without its deleted faces, the consolidated and the temporary faces (each
  // with its own copies of the vertices it uses; edits whose vertices are gone are left out).
  PolygonSoup scene_soup() const;
  PolygonSoup consolidated_soup() const;
  PolygonSoup temporary_soup() const;
  // The three as the pipeline's input, in that order, parts named "scene", "consolidated" and
  // "temporary": faces that only touch at a vertex keep separate vertices there (Joining::across_edges).
  PipelineInput pipeline_input() const;
  // The positions of pipeline_input()'s polygons alone: what a slider that only moved the scene's vertices
  // changes (see input_topology_version). No names, no polygons, no lookups by name.
  Buffer<Vec3> pipeline_positions() const;
  // A new number, unique among all documents, whenever pipeline_input() has other polygons, names or
  // sharpness than before (new scene geometry, an edit, undo, redo); stays when only vertices moved or
  // only the faces' attributes changed.
  std::uint64_t input_topology_version() const { return input_topology_version_; }

  // New attributes (colours) for the scene's faces, their polygons unchanged: the topology version stays
  // and input_attributes_version() grows. Throws InvalidInputError for more values than faces.
  void set_scene_face_attributes(Attributes faces);
  // The face attributes of pipeline_input()'s polygons alone.
  Attributes pipeline_face_attributes() const;
  // Grows whenever pipeline_face_attributes() may have changed (also with every new topology).
  std::uint64_t input_attributes_version() const { return input_attributes_version_; }

 private:
  struct AddTemporary {
    std::vector<EditedFace> faces;
  };
  struct Accept {
    size_t count;
  };
  struct ClearTemporary {
    std::vector<EditedFace> faces;
  };
  struct DeleteFaces {
    std::vector<std::string> scene_faces;
    std::vector<std::pair<size_t, EditedFace>> temporary;  // with their former positions
    std::vector<std::pair<size_t, EditedFace>> consolidated;
  };
  // The edges the command changes, each with its weight before and after (0: not marked).
  struct SetSharp {
    struct Change {
      std::string a, b;
      float before, after;
    };
    std::vector<Change> changes;
  };
  using Command = std::variant<AddTemporary, Accept, ClearTemporary, DeleteFaces, SetSharp>;

  // Faces on one undirected edge: the face and whether it runs from the lower to the higher vertex id.
  struct EdgeUse {
    std::string face;
    bool runs_up;
  };

  void execute(Command command);
  void apply(const Command& command);
  void revert(const Command& command);
  void index_scene();
  // After anything but moved vertices: a new input topology, whose edited vertices' sources are found again.
  void note_new_topology();
  // The scene faces pipeline_input() keeps: all but the deleted ones.
  std::vector<Index> kept_scene_faces() const;
  float text_sharpness(Index u, Index w) const;
  std::vector<EdgeUse> uses_of(Index u, Index w) const;
  // Why a new face cannot be added next to the current faces plus `pending` (faces of the same edit),
  // or empty; with `orient`, reverses it where its neighbours disagree with it.
  // `votes`, when given, receives how many of its edges shared with a face agree minus disagree.
  std::string check_face(EditedFace& face, const std::vector<EditedFace>& pending, bool orient,
                         int* votes = nullptr) const;
  // Adds a zipper strip (faces by vertex names, counted in `strip`) to the temporary mesh, reversed first
  // when `orient` and most of the existing faces along it disagree with it; refused with the reason.
  EditOutcome add_strip(std::vector<EditedFace> faces, const ZipperFaces& strip, bool orient);
  Index vertex_id(const std::string& name) const;
  PolygonSoup edited_soup(const std::vector<EditedFace>& faces) const;
  // The scene vertices edited_soup(faces) copies, in its order.
  std::vector<Index> edited_sources(const std::vector<EditedFace>& faces) const;
  std::string next_face_name() { return "edit" + std::to_string(++face_counter_); }

  PolygonSoup scene_;
  std::unordered_map<std::string, Index> vertex_ids_;
  std::unordered_map<std::string, Index> face_ids_;
  std::unordered_map<std::uint64_t, std::vector<Index>> scene_edge_faces_;

  std::vector<EditedFace> temporary_;
  std::vector<EditedFace> consolidated_;
  std::vector<std::string> deleted_;
  std::vector<NamedSharpEdge> sharp_;
  std::vector<Command> history_;
  size_t done_ = 0;  // history_[0, done_) is applied; the rest can be redone
  std::size_t face_counter_ = 0;
  std::uint64_t input_topology_version_ = 0, input_attributes_version_ = 0;
  std::vector<Index> edited_vertex_sources_;  // of the consolidated and temporary parts, in input order
};

}  // namespace nome
