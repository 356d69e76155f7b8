#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/change.hpp"
#include "nome/ops/pipeline_settings.hpp"
#include "nome/progress.hpp"

namespace nome {

// What a stage's pass is given besides its input mesh.
struct StagePass {
  const PipelineSettings& settings;
  const Progress& progress;            // how far a long pass got ("subdivision", 0..1)
  std::vector<std::string>& warnings;  // of this run, each starting with the stage's task ("offset: ")
};

// One step of the Pipeline: makes its output mesh from the mesh of the stage before it. The pipeline holds
// the cache around it: which pass a run needs (none, positions, topology), from the change the stages
// before it pass on and from the settings; a stage only makes its output.
//
// The topology pass makes the output from an input of new topology (or one the stage has not seen); the
// positions pass gives the output of the last topology pass new positions from an input of the same
// topology (OpenSubdiv's split between refinement and positions). The first stage of a list, the scene,
// has no stage before it: its input is its own mesh, which the pipeline's input calls made.
class PipelineStage {
 public:
  virtual ~PipelineStage() = default;

  // The stage's name: settings select the stage a run stops at by it (to_string(Stage) for the built-in
  // stages), and Pipeline::work reports by it.
  virtual std::string_view name() const = 0;
  // Throws InvalidInputError for settings the stage cannot run with. Asked of every stage a run reaches,
  // before any pass.
  virtual void check(const PipelineSettings&) const {}
  // Whether the stage changes its input under these settings; an off stage hands its input on.
  virtual bool is_on(const PipelineSettings& settings) const = 0;
  // Whether going from the settings of the stage's last pass to `next` needs a topology pass (other
  // level counts), or a positions pass (another rule, another distance).
  virtual bool changes_topology(const PipelineSettings& /*last*/, const PipelineSettings& /*next*/) const {
    return false;
  }
  virtual bool changes_positions(const PipelineSettings& /*last*/, const PipelineSettings& /*next*/) const {
    return false;
  }

  // Makes the output from `input`, a new topology.
  virtual void topology_pass(const Mesh& input, const StagePass& pass) = 0;
  // Moves the output's positions to follow `input`'s. Returns Change::positions, or Change::topology when
  // the stage found it had to make the output anew (the merge joining other vertices).
  virtual Change positions_pass(const Mesh& input, const StagePass& pass) = 0;
  // For each face of the output: the face of `input` it was made from (after a pass on that input). The
  // pipeline carries the input's face attributes by it when a positions pass keeps the faces.
  virtual ElementOrigins face_origins(const Mesh& /*input*/) const { return ElementOrigins::identity(); }
  // Whether the positions pass can run on `input`: what it needs of the last topology pass is there.
  virtual bool can_take_positions(const Mesh& /*input*/) const { return true; }

  // The output of the last pass (the caller may swap it out: Pipeline::lend_result).
  virtual Mesh& result() = 0;
  // The run reached the stage and it is off: returns true when the stage freed its output (its next pass
  // is then a topology pass), false when it keeps it for when it is on again.
  virtual bool free_while_off() { return false; }
  // Frees what only the positions pass needs (a subdivision's refinement), for a one-shot caller's memory:
  // can_take_positions is false until the next topology pass.
  virtual void free_positions_data() {}

  // Edits name the vertices and faces of this stage's output (the scene's, the merge's): the pipeline
  // keeps it and never lends it out. The stages after the first that is not editable are computed.
  virtual bool is_editable() const { return false; }
  // The output's topology report found from the stage's input, without counting the output, or none.
  virtual std::optional<TopologyReport> derived_report(const Mesh& /*input*/) const { return std::nullopt; }
  // The normals a display draws the output with when the stage has them already (Pipeline::display_normals).
  virtual bool display_normals(Buffer<PackedNormal>& /*faces*/, Buffer<PackedNormal>& /*vertices*/,
                               int /*threads*/) const {
    return false;
  }
};

// The built-in stages in order: scene, merged, subdivided, offset, subdivided offset. The one
// place the list is made; a new built-in stage is one line here.
std::vector<std::unique_ptr<PipelineStage>> builtin_stages();

}  // namespace nome
