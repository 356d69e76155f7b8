#pragma once

#include <optional>

#include "nome/ops/pipeline_stage.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

// What the two Catmull-Clark stages (before and after the offset) share: the topology pass builds a
// Refinement and the mesh of its last level, the positions pass refines positions through the kept
// Refinement into that mesh. Another rule needs the positions pass only; other levels, boundary or
// creases a topology pass.
class SubdivisionStage : public PipelineStage {
 public:
  bool is_on(const PipelineSettings& s) const override { return levels(s) > 0; }
  void check(const PipelineSettings& s) const override;
  bool changes_topology(const PipelineSettings& last, const PipelineSettings& next) const override;
  bool changes_positions(const PipelineSettings& last, const PipelineSettings& next) const override {
    return last.rule != next.rule;
  }
  void topology_pass(const Mesh& input, const StagePass& pass) override;
  Change positions_pass(const Mesh& input, const StagePass& pass) override;
  // The refinement, which a positions pass needs, may have been freed (free_positions_data).
  bool can_take_positions(const Mesh& input) const override {
    return refinement_ && refinement_->fits(input);
  }
  ElementOrigins face_origins(const Mesh& input) const override { return refinement_->face_origins(input); }
  Mesh& result() override { return result_; }
  bool free_while_off() override;
  void free_positions_data() override { refinement_.reset(); }
  std::optional<TopologyReport> derived_report(const Mesh& input) const override;
  // The levels the stage makes under these settings (0: off).
  virtual int levels(const PipelineSettings& s) const = 0;

 private:
  std::optional<Refinement> refinement_;
  Mesh result_;
  // Of the last topology pass.
  int levels_ = 0;
  BoundaryMode boundary_ = BoundaryMode::edge_only;
};

}  // namespace nome
