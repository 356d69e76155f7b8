#pragma once

#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/pipeline_input.hpp"
#include "nome/ops/pipeline_stage.hpp"

namespace nome {

// The pipeline's first stage: the input's polygons as one mesh. It keeps what the mesh was built from, so
// that an input whose polygons are the same (only positions or face attributes changed) updates the mesh in
// place: a slider that moves vertices builds no mesh. Its mesh is made as the input arrives, so that a
// topology error reaches the caller that gave the input; its passes at a run hand on the input's problems.
class SceneStage final : public PipelineStage {
 public:
  std::string_view name() const override { return "scene"; }
  bool is_on(const PipelineSettings&) const override { return true; }
  void topology_pass(const Mesh& input, const StagePass& pass) override;
  Change positions_pass(const Mesh& input, const StagePass& pass) override;
  Mesh& result() override { return mesh_; }
  bool is_editable() const override { return true; }

  // Takes the next input and brings the mesh up to date. Throws TopologyError naming the part at fault;
  // the stage then starts over.
  Change update(PipelineInput input);
  // Takes the next input as a new topology (the caller knows): builds the mesh without comparing.
  Change replace(PipelineInput input);
  // Takes a mesh built by the caller as the stage's result (compared with the last one).
  Change update(const Mesh& mesh);
  // New positions for the last input's vertices, its polygons unchanged. Throws InvalidInputError when
  // there is no such input or the count differs.
  Change move_vertices(Buffer<Vec3> positions);
  // New face attributes for the mesh's faces (attributes_changed() then says so). Throws
  // InvalidInputError when there is no mesh or a column holds more values than it has faces.
  Change set_face_attributes(Attributes faces);

  // What the joining left apart: edges of three or more faces (across_edges joining), vertices split
  // where faces only touch (parts that may touch at vertices).
  const std::vector<std::string>& problems() const { return problems_; }
  // Whether the last input changed the faces' attributes (a colour), besides what its Change says.
  bool attributes_changed() const { return attributes_changed_; }

 private:
  // What the mesh was built from, except positions, face attributes and faces (compared by faces_match).
  struct Structure {
    std::vector<std::pair<Index, Index>> sharp_edges;
    std::vector<float> sharp_edge_weights;
    std::vector<std::pair<Index, float>> sharp_vertices;
    std::vector<Index> hole_faces;
    Names vertex_names, face_names;  // shared with the soup and the mesh, not copied
    Index num_vertices = 0;
    Joining joining = Joining::manifold;
    bool operator==(const Structure&) const = default;
  };

  Change take(PipelineInput input, bool may_be_same);
  void rebuild(PipelineInput input);
  void take_positions(Buffer<Vec3>& positions);
  void keep_input_faces(PolygonSoup& soup);
  // Whether these are the faces of the last input: the mesh's own when it was built from them as they were,
  // else the copy kept of them.
  bool faces_match(const Buffer<Index>& face_offsets, const Buffer<Index>& face_vertices) const;

  Structure structure_;
  bool has_input_ = false;  // structure_ describes an input (set by update(PipelineInput))
  // The input's faces, kept only when the mesh's differ from them (joined across edges, or split at
  // vertices); a mesh built as given holds them itself.
  Buffer<Index> input_face_offsets_, input_face_vertices_;
  bool has_mesh_ = false;
  Mesh mesh_;
  std::vector<Index> vertex_sources_;  // mesh vertex -> input vertex (empty: the same numbers)
  std::vector<std::string> problems_;
  bool attributes_changed_ = true;
};

}  // namespace nome
