#pragma once

#include <optional>
#include <string>
#include <vector>

#include "nome/ops/merge.hpp"
#include "nome/ops/pipeline.hpp"
#include "ops/pipeline/solid_stages.hpp"

namespace nome {

// The merge stage, cached: when only the input's positions moved and the merge would join the same
// vertices, the merged mesh's positions are updated in place (no mesh is built).
class MergeStage {
 public:
  // Returns what changed in the merged mesh.
  Change update(const Mesh& input, Change change, double tolerance);
  bool has_mesh() const { return merged_.has_value(); }
  const Mesh& mesh() const { return merged_->mesh; }
  Mesh& mesh() { return merged_->mesh; }
  StageWork work() const { return work_; }
  const MergeSummary& summary() const { return summary_; }

 private:
  std::optional<MergeResult> merged_;
  double tolerance_ = 0.0;  // as asked for (0: relative)
  MergeSummary summary_;
  StageWork work_ = StageWork::skipped;
};

}  // namespace nome
