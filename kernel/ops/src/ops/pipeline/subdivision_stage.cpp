#include "ops/pipeline/subdivision_stage.hpp"

#include "nome/error.hpp"
#include "nome/ops/subdivided_report.hpp"

namespace nome {
namespace {

constexpr int max_levels = 16;

}  // namespace

void SubdivisionStage::check(const PipelineSettings& s) const {
  if (levels(s) < 0 || levels(s) > max_levels)
    throw InvalidInputError("pipeline: subdivision levels must be between 0 and " +
                            std::to_string(max_levels));
}

bool SubdivisionStage::changes_topology(const PipelineSettings& last, const PipelineSettings& next) const {
  return levels(last) != levels(next) || last.boundary != next.boundary || !(last.creases == next.creases);
}

void SubdivisionStage::topology_pass(const Mesh& input, const StagePass& pass) {
  const PipelineSettings& s = pass.settings;
  const int levels = this->levels(s);
  pass.progress("subdivision", 0.0);
  // Into the last refinement's blocks where there is one: a slider that changes the topology then faults
  // in no fresh pages. A refinement that throws is dropped, as a new one would not be kept.
  if (!refinement_) {
    refinement_.emplace(input, levels, s.boundary, s.threads, s.creases);
  } else {
    try {
      refinement_->rebuild(input, levels, s.boundary, s.threads, s.creases);
    } catch (...) {
      refinement_.reset();
      throw;
    }
  }
  levels_ = levels;
  boundary_ = s.boundary;
  pass.progress("subdivision", 0.4);
  Buffer<Vec3> positions(refinement_->num_vertices());
  refinement_->refine_positions(input, s.rule, positions, s.threads);
  pass.progress("subdivision", 0.7);
  result_ = refinement_->mesh(input, std::move(positions), s.threads);
  pass.progress("subdivision", 1.0);
}

Change SubdivisionStage::positions_pass(const Mesh& input, const StagePass& pass) {
  refinement_->refine_positions(input, pass.settings.rule, result_, pass.settings.threads);
  return Change::positions;
}

bool SubdivisionStage::free_while_off() {
  refinement_.reset();
  result_ = {};
  levels_ = 0;
  return true;
}

std::optional<TopologyReport> SubdivisionStage::derived_report(const Mesh& input) const {
  if (!subdivision_outputs_every_face(input, boundary_)) return std::nullopt;
  return subdivided_topology_report(input, levels_);
}

}  // namespace nome
