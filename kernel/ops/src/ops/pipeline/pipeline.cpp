#include "nome/ops/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "nome/error.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/subdivided_report.hpp"
#include "ops/pipeline/merge_stage.hpp"
#include "ops/pipeline/scene_stage.hpp"
#include "ops/pipeline/solid_stages.hpp"

namespace nome {
namespace {

// Bytes a cached quad-mesh stage holds per face: the Mesh with its adjacency (positions, corners,
// edges, fans, about 180) plus the refinement's previous level and level positions (about 40).
constexpr double bytes_per_face = 220.0;
// A last level kept as quads: its corners (16) and positions (about 24), plus the level before it (8).
constexpr double quad_bytes_per_face = 48.0;

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / double(1 << 30));
  return text;
}

void check_budget(const Mesh& input, const PipelineSettings& s, bool streams_last_level) {
  const PipelineEstimate estimate = estimate_pipeline(input, s, streams_last_level);
  if (!s.force && estimate.bytes > double(s.memory_budget))
    throw BudgetError("pipeline: the result would have about " +
                      std::to_string(std::llround(estimate.faces)) + " faces and need about " +
                      gigabytes(estimate.bytes) + ", over the budget of " +
                      gigabytes(double(s.memory_budget)));
}

}  // namespace

PipelineEstimate estimate_pipeline(const Mesh& input, const PipelineSettings& s, bool streams_last_level) {
  double faces = input.num_faces(), corners = input.num_corners(), border = 0, bytes = 0;
  for (const Edge& e : input.edges()) border += e.is_boundary() ? 1 : 0;
  auto subdivide_counts = [&](int levels, bool is_last) {
    if (levels == 0) return;
    faces = corners * std::pow(4.0, levels - 1);
    corners = 4 * faces;
    border *= std::pow(2.0, levels);
    bytes += faces * (is_last && streams_last_level ? quad_bytes_per_face : bytes_per_face);
  };
  subdivide_counts(s.levels_before(), s.distance() == 0);
  if (s.distance() > 0) {
    faces = 2 * faces + border;
    corners = 2 * corners + 4 * border;
    border = 0;
    bytes += faces * bytes_per_face;
    subdivide_counts(s.levels_after(), true);
  }
  return {faces, bytes};
}

Pipeline::Pipeline()
    : scene_(std::make_unique<SceneStage>()),
      merged_(std::make_unique<MergeStage>()),
      solid_(std::make_unique<SolidStages>()) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

void Pipeline::input_changed(Change change) {
  merge_change_ = combined(merge_change_, change);
  solid_change_ = combined(solid_change_, change);
  pending_result_change_ = combined(pending_result_change_, change);
  result_ = nullptr;
  input_warnings_.clear();
  input_warnings_ = scene_->problems();
}

void Pipeline::set_input(PipelineInput input) {
  input_changed(scene_->update(std::move(input)));
}

void Pipeline::replace_input(PipelineInput input) {
  input_changed(scene_->replace(std::move(input)));
}

void Pipeline::move_input_vertices(Buffer<Vec3> positions) {
  input_changed(scene_->move_vertices(std::move(positions)));
}

void Pipeline::set_input(const Mesh& scene_mesh) {
  input_changed(scene_->update(scene_mesh));
}

void Pipeline::set_progress(Progress progress) {
  progress_ = progress;
  solid_->set_progress(std::move(progress));
}

const Mesh& Pipeline::run(const Mesh& scene_mesh, const PipelineSettings& settings) {
  set_input(scene_mesh);
  return run(settings);
}

const Mesh& Pipeline::run(const PipelineSettings& s) {
  return run(s, s, false);
}

const Mesh& Pipeline::run(const PipelineSettings& s, const PipelineSettings& budgeted,
                          bool streams_last_level) {
  try {
    return run_stages(s, budgeted, streams_last_level);
  } catch (...) {
    // Stages that threw start over: whatever the next run shows is a new topology to its caller.
    last_result_ = nullptr;
    throw;
  }
}

void Pipeline::note_result_change(Change change) {
  if (result_ != last_result_) change = Change::topology;
  last_result_ = result_;
  result_change_ = change;
  if (change == Change::topology) ++result_topology_version_;
}

const Mesh& Pipeline::run_stages(const PipelineSettings& s, const PipelineSettings& budgeted,
                                 bool streams_last_level) {
  last_level_.reset();
  Change result_change = std::exchange(pending_result_change_, Change::none);
  warnings_ = std::move(input_warnings_);
  input_warnings_.clear();
  const Mesh* current = &scene_->mesh();
  int source = int(Stage::scene);
  if (s.is_merging()) {
    const Change change = merged_->update(*current, merge_change_, s.merge_tolerance);
    merge_change_ = Change::none;
    result_change = combined(result_change, change);
    if (merged_->work() == StageWork::rebuilt)
      for (const SkippedMerge& skip : merged_->summary().skipped)
        warnings_.push_back("merge: " + skip.message);
    solid_change_ = combined(solid_change_, change);
    current = &merged_->mesh();
    source = int(Stage::merged);
  }
  if (s.stage <= Stage::merged) {
    result_ = current;
    note_result_change(result_change);
    return *result_;
  }
  check_budget(*current, budgeted, streams_last_level);
  if (source != solid_source_) solid_change_ = Change::topology;
  const Change change = solid_change_;
  solid_source_ = -1;  // until the solid stages have run on it
  result_ = &solid_->run(*current, change, s);
  solid_source_ = source;
  solid_change_ = Change::none;
  note_result_change(solid_->result_change());
  for (const std::string& w : solid_->warnings()) warnings_.push_back(w);
  return *result_;
}

namespace {

bool has_sharp_edge(const Mesh& mesh) {
  if (mesh.has_sharpness_weights()) return true;
  return std::any_of(mesh.edges().begin(), mesh.edges().end(), [](const Edge& e) { return e.is_sharp; });
}

}  // namespace

LastSubdivision Pipeline::run_to_last_subdivision(const PipelineSettings& s, bool needs_creases) {
  const bool is_after_offset = s.levels_after() > 0;
  const int levels = is_after_offset ? s.levels_after() : s.distance() > 0 ? 0 : s.levels_before();
  if (levels == 0) return {&run(s), 0};
  PipelineSettings before = s;
  (is_after_offset ? before.subdivision_after : before.subdivision_levels) = 0;
  const Mesh& input = run(before, s, true);
  if (!subdivision_outputs_every_face(input, s.boundary) || (needs_creases && has_sharp_edge(input)))
    return {&run(s), 0};
  return {&input, levels};
}

const Mesh* Pipeline::run_to_last_offset(const PipelineSettings& s) {
  if (!(s.distance() > 0 && s.levels_after() == 0)) return nullptr;
  PipelineSettings before = s;
  before.stage = Stage::subdivided;
  return &run(before, s, false);
}

Normals Pipeline::offset_normals(const Mesh& input, int threads) {
  Normals normals;
  compute_normals(input, normals, threads);
  if (std::string warning = degeneracy_warning(input, normals); !warning.empty())
    warnings_.push_back("offset: " + warning);
  return normals;
}

void Pipeline::run_before_surface(const PipelineSettings& s, bool needs_creases) {
  if (!run_to_last_offset(s)) run_to_last_subdivision(s, needs_creases);
}

PipelineSurface Pipeline::run_offset_surface(const Mesh& input, const PipelineSettings& s,
                                             bool needs_creases) {
  // The offset's edges copy the input's sharp marks: only its Mesh carries them.
  if (needs_creases && has_sharp_edge(input)) return {&run(s), std::nullopt, std::nullopt};
  progress_("offset", 0.0);
  // A writer's one pass: the subdivision's refinement is not needed again, and the normals take its
  // blocks instead of fresh pages; the face normals go back as soon as the vertex normals are made.
  solid_->release_refinements();
  Normals normals = offset_normals(input, s.threads);
  normals.faces = {};
  PipelineSurface surface{nullptr, std::nullopt,
                          OffsetSurface(input, std::move(normals.vertices), s.distance())};
  progress_("offset", 1.0);
  return surface;
}

PipelineSurface Pipeline::run_surface(const PipelineSettings& s, bool needs_creases) {
  if (const Mesh* input = run_to_last_offset(s)) return run_offset_surface(*input, s, needs_creases);
  const LastSubdivision last = run_to_last_subdivision(s, needs_creases);
  if (last.levels == 0) return {last.input, std::nullopt, std::nullopt};
  progress_("subdivision", 0.0);
  last_level_.emplace(*last.input, last.levels, s.boundary, s.threads, s.creases);
  progress_("subdivision", 0.5);
  const std::span<const Vec3> positions = last_level_->refine_positions(*last.input, s.rule, s.threads);
  progress_("subdivision", 1.0);
  return {nullptr, QuadSurface{positions, last_level_->quad_vertices()}, std::nullopt};
}

Mesh Pipeline::take_result() {
  Mesh out;
  if (result_ == &scene_->mesh()) {
    out = std::move(scene_->mesh());
  } else if (merged_->has_mesh() && result_ == &merged_->mesh()) {
    out = std::move(merged_->mesh());
  } else if (std::optional<Mesh> solid = solid_->take_result()) {
    out = std::move(*solid);
  }
  *this = Pipeline();
  return out;
}

bool Pipeline::is_solid_result() const {
  return result_ && result_ != &scene_->mesh() && !(merged_->has_mesh() && result_ == &merged_->mesh());
}

bool Pipeline::display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                               int threads) const {
  return is_solid_result() && solid_->display_normals(faces, vertices, threads);
}

bool Pipeline::exchange_result_positions(Buffer<Vec3>& positions) {
  return is_solid_result() && solid_->exchange_result_positions(positions);
}

bool Pipeline::lend_result(Mesh& mesh, std::function<Mesh()> copy_back) {
  return is_solid_result() && solid_->lend_result(mesh, std::move(copy_back));
}

TopologyReport Pipeline::result_report() const {
  if (!result_) return {};
  if (is_solid_result())
    if (std::optional<TopologyReport> report = solid_->derived_report()) return std::move(*report);
  return topology_report(*result_);
}

StageWork Pipeline::work(Stage stage) const {
  if (stage == Stage::scene) return scene_->work();
  if (stage == Stage::merged) return merged_->work();
  return solid_->work(stage);
}

const MergeSummary& Pipeline::merge_summary() const {
  return merged_->summary();
}

}  // namespace nome
