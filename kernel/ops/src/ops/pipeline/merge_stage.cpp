#include "ops/pipeline/merge_stage.hpp"

namespace nome {

Change MergeStage::update(const Mesh& input, Change change, double tolerance) {
  if (merged_ && change == Change::none && tolerance == tolerance_) {
    work_ = StageWork::cached;
    return Change::none;
  }
  const MergeOptions options{.tolerance = tolerance};
  MergePlan plan = plan_merge(input, options);
  summary_.tolerance = plan.tolerance;
  if (merged_ && change == Change::positions && plan.vertex_map == merged_->vertex_map) {
    merged_positions(input, plan, merged_->mesh.positions());
    merged_->mesh.face_colors() = input.face_colors();
    merged_->tolerance = plan.tolerance;
    tolerance_ = tolerance;
    summary_.skipped = std::move(plan.skipped);
    work_ = StageWork::positions;
    return Change::positions;
  }
  merged_.reset();
  merged_ = merge_by_plan(input, std::move(plan));
  tolerance_ = tolerance;
  summary_.glued_edges = merged_->glued_edges;
  summary_.skipped = merged_->skipped;
  work_ = StageWork::rebuilt;
  return Change::topology;
}

}  // namespace nome
