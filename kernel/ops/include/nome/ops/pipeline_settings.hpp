#pragma once

#include <cstdint>

#include "nome/ops/stage.hpp"
#include "nome/ops/subdivide.hpp"

namespace nome {

// Everything that decides what the pipeline makes: the stage asked for and how each stage is made. The
// command line fills it from its options, the viewer from its control panel.
struct PipelineSettings {
  Stage stage = Stage::subdivided_offset;  // the last stage made; the ones after it are skipped
  bool should_merge = false;               // the stages after `merged` start from the merged mesh
  double merge_tolerance = 0.0;            // 0: relative to the size of the scene (MergeOptions)
  int subdivision_levels = 0;              // Catmull-Clark levels before the offset
  SubdivisionRule rule = SubdivisionRule::classic;
  BoundaryMode boundary = BoundaryMode::edge_only;
  CreaseOptions creases = {};    // how crease weights decay; smooth triangles
  double offset_distance = 0.0;  // 0: no offset; otherwise positive and finite
  int subdivision_after = 0;     // levels after the offset (needs an offset)
  bool force = false;            // compute even when the estimate exceeds the memory budget
  std::uint64_t memory_budget = std::uint64_t(4) << 30;
  int threads = 1;

  bool operator==(const PipelineSettings&) const = default;

  // What the stage asked for uses: a stage after it is off (no levels, no distance, no merge).
  bool is_merging() const {
    return stage == Stage::merged || (should_merge && passes_through(stage, Stage::merged));
  }
  int levels_before() const { return passes_through(stage, Stage::subdivided) ? subdivision_levels : 0; }
  double distance() const { return passes_through(stage, Stage::offset) ? offset_distance : 0.0; }
  int levels_after() const { return stage == Stage::subdivided_offset ? subdivision_after : 0; }
  // The result is a subdivision surface (some level of Catmull-Clark ran), not the faces as made.
  bool is_smoothing() const { return levels_before() > 0 || levels_after() > 0; }
};

}  // namespace nome
