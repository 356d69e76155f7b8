#include "ops/pipeline/solid_stages.hpp"

#include <cmath>

#include "nome/error.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/offset_normals.hpp"
#include "nome/ops/offset_report.hpp"
#include "nome/ops/subdivided_report.hpp"

namespace nome {
namespace {

constexpr int max_levels = 16;

void check_settings(const PipelineSettings& s) {
  if (s.levels_before() < 0 || s.levels_before() > max_levels || s.levels_after() < 0 ||
      s.levels_after() > max_levels)
    throw InvalidInputError("pipeline: subdivision levels must be between 0 and " +
                            std::to_string(max_levels));
  if (s.distance() != 0.0 && !(s.distance() > 0.0 && std::isfinite(s.distance())))
    throw InvalidInputError("pipeline: the offset distance must be positive and finite, got " +
                            std::to_string(s.distance()));
  if (s.levels_after() > 0 && s.distance() == 0.0)
    throw InvalidInputError("pipeline: subdivision after the offset needs an offset distance");
}

}  // namespace

const Mesh& SolidStages::run(const Mesh& input, Change change, const PipelineSettings& s) {
  check_settings(s);
  warnings_.clear();
  const bool is_first_run = !last_settings_;
  const PipelineSettings previous = last_settings_.value_or(s);
  last_settings_ = s;
  has_new_topology_ = is_first_run || change == Change::topology;
  has_new_positions_ = has_new_topology_ || change == Change::positions || has_exchanged_result_;
  has_exchanged_result_ = false;
  input_ = &input;
  try {
    const Mesh& result = run_stages(input, s, previous);
    // A result still lent out was made anew or its stage left out: its copy is not needed.
    lent_ = nullptr;
    copy_back_ = nullptr;
    return result;
  } catch (...) {
    // A stage left half done must not pass for a cached one next time.
    Progress progress = std::move(progress_);
    *this = SolidStages();
    progress_ = std::move(progress);
    throw;
  }
}

const Mesh& SolidStages::run_stages(const Mesh& input, const PipelineSettings& s,
                                    const PipelineSettings& previous) {
  const Mesh* current = &input;
  result_ = nullptr;
  before_.work = after_.work = offset_.work = StageWork::skipped;
  if (s.levels_before() > 0) {
    has_new_positions_ = has_new_positions_ || s.rule != previous.rule;
    current = result_ = &subdivide_stage(before_, *current, s.levels_before(), s);
  } else {
    // The offset now starts from the input itself, no longer from the subdivision's result.
    has_new_topology_ = has_new_topology_ || previous.levels_before() > 0;
    has_new_positions_ = has_new_positions_ || has_new_topology_;
    before_ = {};
  }
  if (s.distance() > 0) {
    has_new_positions_ = has_new_positions_ || s.distance() != previous.distance();
    current = result_ = &offset_stage(*current, s);
    if (s.levels_after() > 0) {
      has_new_positions_ = has_new_positions_ || s.rule != previous.rule;
      current = result_ = &subdivide_stage(after_, *current, s.levels_after(), s);
    } else {
      after_ = {};
    }
  } else {
    offset_ = {};
    after_ = {};
  }
  return *current;
}

std::optional<Mesh> SolidStages::take_result() {
  std::optional<Mesh> out;
  if (result_) out = std::move(*result_);
  Progress progress = std::move(progress_);
  *this = SolidStages();
  progress_ = std::move(progress);
  return out;
}

bool SolidStages::display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                                  int threads) const {
  if (!result_ || result_ != &offset_.result || !offset_.input) return false;
  return offset_packed_normals(*offset_.input, offset_.normals, faces, vertices, threads);
}

bool SolidStages::exchange_result_positions(Buffer<Vec3>& positions) {
  if (!result_ || positions.size() != result_->num_vertices()) return false;
  result_->positions().swap(positions);
  has_exchanged_result_ = true;
  return true;
}

bool SolidStages::lend_result(Mesh& mesh, std::function<Mesh()> copy_back) {
  if (!result_) return false;
  std::swap(*result_, mesh);
  lent_ = result_;
  copy_back_ = std::move(copy_back);
  return true;
}

bool SolidStages::takes_back(Mesh& result) {
  if (&result != lent_) return true;
  lent_ = nullptr;
  const std::function<Mesh()> copy = std::move(copy_back_);
  copy_back_ = nullptr;
  if (!copy) return false;
  result = copy();
  return true;
}

std::optional<TopologyReport> SolidStages::derived_report() const {
  if (!result_) return std::nullopt;
  if (result_ == &offset_.result) return offset_topology_report(*offset_.input);
  const bool is_after = result_ == &after_.result;
  const Mesh& in = is_after ? offset_.result : *input_;
  const SubdivisionStage& stage = is_after ? after_ : before_;
  if (!subdivision_outputs_every_face(in, stage.boundary)) return std::nullopt;
  return subdivided_topology_report(in, stage.levels);
}

void SolidStages::release_refinements() {
  before_.refinement.reset();
  after_.refinement.reset();
}

StageWork SolidStages::work(Stage stage) const {
  switch (stage) {
    case Stage::subdivided:
      return before_.work;
    case Stage::offset:
      return offset_.work;
    case Stage::subdivided_offset:
      return after_.work;
    default:
      return StageWork::skipped;
  }
}

Mesh& SolidStages::subdivide_stage(SubdivisionStage& stage, const Mesh& in, int levels,
                                   const PipelineSettings& s) {
  // The result stands for the settings it was made with; the refinement, which a position pass needs, may
  // have been released (release_refinements).
  const bool is_same_topology = !has_new_topology_ && stage.levels == levels &&
                                stage.boundary == s.boundary && stage.creases == s.creases &&
                                (!stage.refinement || stage.refinement->fits(in));
  const bool reuses_result =
      is_same_topology && !(has_new_positions_ && !stage.refinement) && takes_back(stage.result);
  if (!reuses_result) {
    progress_("subdivision", 0.0);
    // Into the last refinement's blocks where there is one: a slider that changes the topology then
    // faults in no fresh pages. A refinement that throws is dropped, as a new one would not be kept.
    if (!stage.refinement) {
      stage.refinement.emplace(in, levels, s.boundary, s.threads, s.creases);
    } else {
      try {
        stage.refinement->rebuild(in, levels, s.boundary, s.threads, s.creases);
      } catch (...) {
        stage.refinement.reset();
        throw;
      }
    }
    stage.levels = levels;
    stage.boundary = s.boundary;
    stage.creases = s.creases;
    progress_("subdivision", 0.4);
    Buffer<Vec3> positions(stage.refinement->num_vertices());
    stage.refinement->refine_positions(in, s.rule, positions, s.threads);
    progress_("subdivision", 0.7);
    stage.result = stage.refinement->mesh(in, std::move(positions), s.threads);
    progress_("subdivision", 1.0);
    stage.work = StageWork::rebuilt;
    has_new_topology_ = has_new_positions_ = true;
  } else if (has_new_positions_) {
    stage.refinement->refine_positions(in, s.rule, stage.result, s.threads);
    stage.work = StageWork::positions;
  } else {
    stage.work = StageWork::cached;
  }
  return stage.result;
}

Mesh& SolidStages::offset_stage(const Mesh& in, const PipelineSettings& s) {
  offset_.input = &in;
  const bool reuses_result = !has_new_topology_ && offset_.has_result && takes_back(offset_.result);
  if (reuses_result && !has_new_positions_) {
    offset_.work = StageWork::cached;
    return offset_.result;
  }
  progress_("offset", 0.0);
  const Normals& normals = offset_.normals;
  compute_normals(in, offset_.normals, s.threads);
  progress_("offset", 0.3);
  if (std::string warning = degeneracy_warning(in, normals); !warning.empty())
    warnings_.push_back("offset: " + warning);
  if (!reuses_result) {
    offset_into(in, normals, s.distance(), offset_.result, s.threads);
    offset_.has_result = true;
    offset_.work = StageWork::rebuilt;
    has_new_topology_ = has_new_positions_ = true;
  } else {
    offset_positions(in, normals, s.distance(), offset_.result.positions(), s.threads);
    offset_.work = StageWork::positions;
  }
  progress_("offset", 1.0);
  return offset_.result;
}

}  // namespace nome
