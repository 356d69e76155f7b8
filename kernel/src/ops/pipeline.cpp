#include "nome/ops/pipeline.hpp"

#include <cmath>
#include <cstdio>

#include "nome/error.hpp"
#include "nome/ops/normals.hpp"
#include "nome/ops/offset.hpp"

namespace nome {
namespace {

// Bytes a cached quad-mesh stage holds per face: the Mesh with its adjacency (positions, corners,
// edges, fans, about 180) plus the refinement's previous level and level positions (about 40).
constexpr double bytes_per_face = 220.0;
constexpr int max_levels = 16;

std::vector<Index> sharp_edges(const Mesh& mesh) {
  std::vector<Index> sharp;
  for (Index e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge(e).is_sharp) sharp.push_back(e);
  return sharp;
}

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / double(1 << 30));
  return text;
}

void check_options(const PipelineOptions& o) {
  if (o.subdivision_levels < 0 || o.subdivision_levels > max_levels || o.subdivision_after < 0 ||
      o.subdivision_after > max_levels)
    throw InvalidInputError("pipeline: subdivision levels must be between 0 and " +
                            std::to_string(max_levels));
  if (o.offset_distance != 0.0 && !(o.offset_distance > 0.0 && std::isfinite(o.offset_distance)))
    throw InvalidInputError("pipeline: the offset distance must be positive and finite, got " +
                            std::to_string(o.offset_distance));
  if (o.subdivision_after > 0 && o.offset_distance == 0.0)
    throw InvalidInputError("pipeline: subdivision after the offset needs an offset distance");
}

}  // namespace

PipelineEstimate estimate_pipeline(const Mesh& input, const PipelineOptions& o) {
  double faces = input.num_faces(), corners = input.num_corners(), border = 0, bytes = 0;
  for (const Edge& e : input.edges()) border += e.is_boundary() ? 1 : 0;
  auto subdivide_counts = [&](int levels) {
    if (levels == 0) return;
    faces = corners * std::pow(4.0, levels - 1);
    corners = 4 * faces;
    border *= std::pow(2.0, levels);
    bytes += faces * bytes_per_face;
  };
  subdivide_counts(o.subdivision_levels);
  if (o.offset_distance > 0) {
    faces = 2 * faces + border;
    corners = 2 * corners + 4 * border;
    border = 0;
    bytes += faces * bytes_per_face;
    subdivide_counts(o.subdivision_after);
  }
  return {faces, bytes};
}

const Mesh& Pipeline::run(const Mesh& input, const PipelineOptions& o) {
  check_options(o);
  const PipelineEstimate estimate = estimate_pipeline(input, o);
  if (!o.force && estimate.bytes > double(o.memory_budget))
    throw BudgetError("pipeline: the result would have about " +
                      std::to_string(std::llround(estimate.faces)) + " faces and need about " +
                      gigabytes(estimate.bytes) + ", over the budget of " +
                      gigabytes(double(o.memory_budget)));
  warnings_.clear();

  // phase: what changed in the input since the last run.
  std::vector<Index> sharp = sharp_edges(input);
  topology_changed_ = input.face_offsets() != input_face_offsets_ ||
                      input.corner_vertices() != input_corners_ || sharp != input_sharp_;
  positions_changed_ = topology_changed_ || input.positions() != input_positions_;
  const bool first_run = !last_options_;
  const PipelineOptions previous = last_options_.value_or(o);
  if (topology_changed_) {
    input_face_offsets_ = input.face_offsets();
    input_corners_ = input.corner_vertices();
    input_sharp_ = std::move(sharp);
  }
  if (positions_changed_) input_positions_ = input.positions();
  last_options_ = o;
  try {
    return run_stages(input, o, previous, first_run);
  } catch (...) {
    // A stage left half done must not pass for a cached one next time.
    *this = Pipeline();
    throw;
  }
}

const Mesh& Pipeline::run_stages(const Mesh& input, const PipelineOptions& o, const PipelineOptions& previous,
                                 bool first_run) {
  // The merge stage (issue 5) goes here: input -> one merged Mesh, its own cache and change flags.
  const Mesh* current = &input;
  result_ = nullptr;

  before_.work = after_.work = offset_.work = StageWork::skipped;
  if (o.subdivision_levels > 0) {
    positions_changed_ = positions_changed_ || first_run || o.rule != previous.rule;
    current = result_ = &subdivide_stage(before_, *current, o.subdivision_levels, o);
  } else {
    before_ = {};
  }
  if (o.offset_distance > 0) {
    positions_changed_ = positions_changed_ || o.offset_distance != previous.offset_distance;
    current = result_ = &offset_stage(*current, o);
    if (o.subdivision_after > 0) {
      positions_changed_ = positions_changed_ || o.rule != previous.rule;
      current = result_ = &subdivide_stage(after_, *current, o.subdivision_after, o);
    } else {
      after_ = {};
    }
  } else {
    offset_ = {};
    after_ = {};
  }
  return *current;
}

Mesh Pipeline::take_result(const Mesh& input) {
  Mesh out = result_ ? std::move(*result_) : input;
  *this = Pipeline();
  return out;
}

Mesh& Pipeline::subdivide_stage(SubdivisionStage& stage, const Mesh& in, int levels,
                                const PipelineOptions& o) {
  if (topology_changed_ || !stage.refinement || stage.levels != levels) {
    stage.refinement.emplace(in, levels, o.threads);
    stage.levels = levels;
    Buffer<Vec3> positions(stage.refinement->num_vertices());
    stage.refinement->refine_positions(in, o.rule, positions, o.threads);
    stage.result = stage.refinement->mesh(in, std::move(positions), o.threads);
    stage.work = StageWork::rebuilt;
    topology_changed_ = positions_changed_ = true;
  } else if (positions_changed_) {
    stage.refinement->refine_positions(in, o.rule, stage.result.positions(), o.threads);
    stage.work = StageWork::positions;
  } else {
    stage.work = StageWork::cached;
  }
  return stage.result;
}

Mesh& Pipeline::offset_stage(const Mesh& in, const PipelineOptions& o) {
  if (!topology_changed_ && !positions_changed_ && offset_.has_result) {
    offset_.work = StageWork::cached;
    return offset_.result;
  }
  const Normals& normals = offset_.normals;
  compute_normals(in, offset_.normals);
  if (std::string warning = degeneracy_warning(in, normals); !warning.empty())
    warnings_.push_back("offset: " + warning);
  if (topology_changed_ || !offset_.has_result) {
    offset_into(in, normals, o.offset_distance, offset_.result, o.threads);
    offset_.has_result = true;
    offset_.work = StageWork::rebuilt;
    topology_changed_ = positions_changed_ = true;
  } else {
    offset_positions(in, normals, o.offset_distance, offset_.result.positions());
    offset_.work = StageWork::positions;
  }
  return offset_.result;
}

}  // namespace nome
