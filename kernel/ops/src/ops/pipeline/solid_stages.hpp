#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/change.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

// The stages after the merge (subdivide k -> offset d -> subdivide j), each result cached. A run redoes
// only what its input's change and the settings invalidate: a new topology (or other level counts)
// rebuilds a stage's topology; new positions, another rule or another distance only re-run its position
// pass over the cached topology (the interactive fast path: a slider that moves vertices).
class SolidStages {
 public:
  // The last stage's result, or `input` when no stage runs (valid until the next run). Throws
  // InvalidInputError for settings out of range.
  const Mesh& run(const Mesh& input, Change change, const PipelineSettings& settings);
  // What the last run changed in its result (its stages' input change carried through them).
  Change result_change() const {
    return has_new_topology_ ? Change::topology : has_new_positions_ ? Change::positions : Change::none;
  }
  // Moves the last stage's result out (none ran: none); the caches start over.
  std::optional<Mesh> take_result();

  // Frees the subdivision stages' refinements (a one-shot caller's memory for its next stage): their
  // results stay cached, and the next run that moves vertices rebuilds them.
  void release_refinements();
  StageWork work(Stage stage) const;
  void set_progress(Progress progress) { progress_ = std::move(progress); }
  // The last result's display normals when it is an offset of two parallel copies (offset_packed_normals:
  // the surface's normals, already computed for the offset), else false.
  bool display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices, int threads) const;
  // Pipeline::exchange_result_positions for the last stage's result: false where no stage ran.
  bool exchange_result_positions(Buffer<Vec3>& positions);
  // Pipeline::lend_result for the last stage's result: false where no stage ran.
  bool lend_result(Mesh& mesh, std::function<Mesh()> copy_back);
  // The last result's topology report found from its stage's input (Pipeline::result_report), or none
  // where no stage ran or the last subdivision drops faces.
  std::optional<TopologyReport> derived_report() const;
  // Warnings of the last run (degenerate faces met by the offset's normals).
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct SubdivisionStage {
    std::optional<Refinement> refinement;
    Mesh result;
    int levels = 0;  // 0: no result
    BoundaryMode boundary = BoundaryMode::edge_only;
    CreaseOptions creases;
    StageWork work = StageWork::skipped;
  };
  struct OffsetStage {
    Normals normals;              // of the stage's input; kept for their blocks, as is the result's
    const Mesh* input = nullptr;  // of the last run (valid as long as its result)
    Mesh result;
    bool has_result = false;
    StageWork work = StageWork::skipped;
  };

  const Mesh& run_stages(const Mesh& input, const PipelineSettings& s, const PipelineSettings& previous);
  // Each returns the stage's output and updates the change flags for the stages after it.
  Mesh& subdivide_stage(SubdivisionStage& stage, const Mesh& in, int levels, const PipelineSettings& s);
  Mesh& offset_stage(const Mesh& in, const PipelineSettings& s);
  // Whether a stage may take up its `result` again: true unless it is lent out and cannot be copied
  // back (then the stage makes it anew).
  bool takes_back(Mesh& result);

  std::optional<PipelineSettings> last_settings_;
  bool has_new_topology_ = true;       // of the current stage's input, during a run
  bool has_new_positions_ = true;      // likewise
  bool has_exchanged_result_ = false;  // its positions are another array's since the last run
  SubdivisionStage before_, after_;
  OffsetStage offset_;
  std::vector<std::string> warnings_;
  Progress progress_;
  Mesh* result_ = nullptr;  // the last stage that ran, or none when the result is the input
  Mesh* lent_ = nullptr;    // a result lent out (lend_result) and not taken back
  std::function<Mesh()> copy_back_;
  const Mesh* input_ = nullptr;  // of the last run
};

}  // namespace nome
