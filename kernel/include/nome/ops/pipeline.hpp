#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/normals.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

struct PipelineOptions {
  int subdivision_levels = 0;  // Catmull-Clark levels before the offset
  SubdivisionRule rule = SubdivisionRule::classic;
  double offset_distance = 0.0;  // 0: no offset; otherwise positive and finite
  int subdivision_after = 0;     // levels after the offset (needs an offset)
  bool force = false;            // compute even when the estimate exceeds the memory budget
  std::uint64_t memory_budget = std::uint64_t(4) << 30;
  int threads = 1;
};

// The size of a pipeline's result, estimated from counts before anything is computed.
struct PipelineEstimate {
  double faces = 0;  // of the final result
  double bytes = 0;  // every cached stage together
};

PipelineEstimate estimate_pipeline(const Mesh& input, const PipelineOptions& options);

// What a stage did in the last run.
enum class StageWork { skipped, cached, positions, rebuilt };

// The stages after the scene (DESIGN.md: subdivide k -> offset d -> subdivide j), each result cached.
// A run redoes only what its inputs invalidate: a new input topology (or other level counts) rebuilds
// a stage's topology; new positions, another rule or another distance only re-run its position pass
// over the cached topology (the interactive fast path: a slider that moves vertices).
class Pipeline {
 public:
  // Returns the result (valid until the next run). Throws InvalidInputError for options out of range
  // and BudgetError, with the estimate, when the result would exceed the memory budget unless forced.
  const Mesh& run(const Mesh& input, const PipelineOptions& options);

  // Moves the last result out (for a one-shot caller such as the CLI); the caches start over.
  Mesh take_result(const Mesh& input);

  // Warnings of the last run (degenerate faces met by the offset's normals), for the caller to show.
  const std::vector<std::string>& warnings() const { return warnings_; }
  StageWork subdivision_work() const { return before_.work; }
  StageWork offset_work() const { return offset_.work; }
  StageWork subdivision_after_work() const { return after_.work; }

 private:
  struct SubdivisionStage {
    std::optional<Refinement> refinement;
    Mesh result;
    int levels = 0;
    StageWork work = StageWork::skipped;
  };
  struct OffsetStage {
    Normals normals;  // of the stage's input; kept for their blocks, as is the result's
    Mesh result;
    bool has_result = false;
    StageWork work = StageWork::skipped;
  };

  const Mesh& run_stages(const Mesh& input, const PipelineOptions& o, const PipelineOptions& previous,
                         bool first_run);
  // Each returns the stage's output and updates the change flags for the stages after it.
  Mesh& subdivide_stage(SubdivisionStage& stage, const Mesh& in, int levels, const PipelineOptions& o);
  Mesh& offset_stage(const Mesh& in, const PipelineOptions& o);

  // What the last run saw: the input's topology and positions, and the options.
  Buffer<Index> input_face_offsets_, input_corners_;
  std::vector<Index> input_sharp_;
  Buffer<Vec3> input_positions_;
  std::optional<PipelineOptions> last_options_;
  bool topology_changed_ = true;   // of the current stage's input, during a run
  bool positions_changed_ = true;  // likewise
  SubdivisionStage before_, after_;
  OffsetStage offset_;
  std::vector<std::string> warnings_;
  Mesh* result_ = nullptr;  // the last stage that ran, or none when the result is the input
};

}  // namespace nome
