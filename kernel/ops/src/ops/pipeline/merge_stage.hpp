#pragma once

#include <optional>
#include <string_view>

#include "nome/ops/merge.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/pipeline_stage.hpp"

namespace nome {

// The merge stage: when only the input's positions moved and the merge would join the same vertices, the
// positions pass updates the merged mesh's positions in place (no mesh is built). It keeps its mesh while
// off, so that merging again after a look at the scene costs nothing.
class MergeStage final : public PipelineStage {
 public:
  std::string_view name() const override { return "merged"; }
  bool is_on(const PipelineSettings& s) const override { return s.is_merging(); }
  bool changes_topology(const PipelineSettings& last, const PipelineSettings& next) const override {
    return last.merge_tolerance != next.merge_tolerance;
  }
  void topology_pass(const Mesh& input, const StagePass& pass) override;
  Change positions_pass(const Mesh& input, const StagePass& pass) override;
  Mesh& result() override { return merged_->mesh; }
  bool is_editable() const override { return true; }

  const MergeSummary& summary() const { return summary_; }

 private:
  void merge(const Mesh& input, MergePlan plan, const StagePass& pass);

  std::optional<MergeResult> merged_;
  MergeSummary summary_;
};

}  // namespace nome
