#include "ops/pipeline/merge_stage.hpp"

#include <utility>

namespace nome {

void MergeStage::merge(const Mesh& input, MergePlan plan, const StagePass& pass) {
  merged_.reset();
  merged_ = merge_by_plan(input, std::move(plan));
  summary_.glued_edges = merged_->glued_edges;
  summary_.skipped = merged_->skipped;
  for (const SkippedMerge& skip : summary_.skipped) pass.warnings.push_back("merge: " + skip.message);
}

void MergeStage::topology_pass(const Mesh& input, const StagePass& pass) {
  MergePlan plan = plan_merge(input, MergeOptions{.tolerance = pass.settings.merge_tolerance});
  summary_.tolerance = plan.tolerance;
  merge(input, std::move(plan), pass);
}

Change MergeStage::positions_pass(const Mesh& input, const StagePass& pass) {
  MergePlan plan = plan_merge(input, MergeOptions{.tolerance = pass.settings.merge_tolerance});
  summary_.tolerance = plan.tolerance;
  if (plan.vertex_map != merged_->vertex_map) {
    merge(input, std::move(plan), pass);
    return Change::topology;
  }
  merged_positions(input, plan, merged_->mesh.positions());
  merged_->tolerance = plan.tolerance;
  summary_.skipped = std::move(plan.skipped);
  return Change::positions;
}

}  // namespace nome
