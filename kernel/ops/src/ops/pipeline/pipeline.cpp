#include "nome/ops/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "nome/error.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/subdivided_report.hpp"
#include "ops/pipeline/merge_stage.hpp"
#include "ops/pipeline/offset_stage.hpp"
#include "ops/pipeline/scene_stage.hpp"
#include "ops/pipeline/subdivide_stage.hpp"
#include "ops/pipeline/subdivided_offset_stage.hpp"

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

std::vector<std::unique_ptr<PipelineStage>> builtin_stages() {
  std::vector<std::unique_ptr<PipelineStage>> stages;
  stages.push_back(std::make_unique<SceneStage>());
  stages.push_back(std::make_unique<MergeStage>());
  stages.push_back(std::make_unique<SubdivideStage>());
  stages.push_back(std::make_unique<OffsetStage>());
  stages.push_back(std::make_unique<SubdividedOffsetStage>());
  return stages;
}

Pipeline::Pipeline() : Pipeline(builtin_stages) {}

Pipeline::Pipeline(MakeStages make_stages) : make_stages_(std::move(make_stages)) {
  for (std::unique_ptr<PipelineStage>& stage : make_stages_()) {
    slots_.emplace_back();
    slots_.back().stage = std::move(stage);
  }
  if (slots_.empty() || !dynamic_cast<SceneStage*>(slots_.front().stage.get()))
    throw InvalidInputError("pipeline: the first stage must be the scene stage");
}

Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

SceneStage& Pipeline::scene() {
  return static_cast<SceneStage&>(*slots_.front().stage);
}

int Pipeline::find(std::string_view stage_name) const {
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].stage->name() == stage_name) return int(i);
  return -1;
}

void Pipeline::input_changed(Change change) {
  slots_.front().pending = combined(slots_.front().pending, change);
  if (change != Change::none && scene().attributes_changed())
    for (Slot& slot : slots_) slot.attributes_pending = true;
  result_ = -1;
}

void Pipeline::set_input(PipelineInput input) {
  input_changed(scene().update(std::move(input)));
}

void Pipeline::replace_input(PipelineInput input) {
  input_changed(scene().replace(std::move(input)));
}

void Pipeline::move_input_vertices(Buffer<Vec3> positions) {
  input_changed(scene().move_vertices(std::move(positions)));
}

void Pipeline::set_input_face_attributes(Attributes faces) {
  input_changed(scene().set_face_attributes(std::move(faces)));
}

void Pipeline::set_input(const Mesh& scene_mesh) {
  input_changed(scene().update(scene_mesh));
}

void Pipeline::set_progress(Progress progress) {
  progress_ = std::move(progress);
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
  return run_to(stop(s), s, budgeted, streams_last_level);
}

const Mesh& Pipeline::run_to(int last, const PipelineSettings& s, const PipelineSettings& budgeted,
                             bool streams_last_level) {
  try {
    return run_stages(last, s, budgeted, streams_last_level);
  } catch (...) {
    // Stages that threw start over: whatever the next run shows is a new topology to its caller.
    last_result_ = -1;
    throw;
  }
}

void Pipeline::note_result_change(Change change) {
  if (result_ != last_result_) change = Change::topology;
  last_result_ = result_;
  result_change_ = change;
  if (change == Change::topology) ++result_topology_version_;
}

bool Pipeline::takes_back(Slot& slot) {
  const std::function<Mesh()> copy = std::move(slot.copy_back);
  forget_lent(slot);
  if (!copy) return false;
  slot.stage->result() = copy();
  return true;
}

void Pipeline::forget_lent(Slot& slot) {
  slot.is_lent = false;
  slot.copy_back = nullptr;
}

Change Pipeline::run_stage(int i, int source, const PipelineSettings& s) {
  Slot& slot = slots_[i];
  PipelineStage& stage = *slot.stage;
  const Mesh& input = slots_[source].stage->result();
  Change change = slot.pending;
  if (!slot.has_result || slot.source != source || stage.changes_topology(slot.settings, s))
    change = Change::topology;
  else if (stage.changes_positions(slot.settings, s))
    change = combined(change, Change::positions);
  if (change == Change::positions && !stage.can_take_positions(input)) change = Change::topology;
  // A result lent out and not copied back is made anew.
  if (change != Change::topology && slot.is_lent && !takes_back(slot)) change = Change::topology;
  if (change == Change::topology) forget_lent(slot);
  slot.pending = Change::none;
  slot.has_result = false;  // until the pass is done: a stage left half done is made anew next time
  const StagePass pass{s, progress_, warnings_};
  if (change == Change::topology) {
    stage.topology_pass(input, pass);
  } else if (change == Change::positions) {
    change = stage.positions_pass(input, pass);
    // The faces stayed; their attributes may not have (a colour changed in the scene).
    if (change == Change::positions && slot.attributes_pending && source != i)
      stage.result().face_attributes() = carried(input.face_attributes(), stage.face_origins(input));
  }
  slot.attributes_pending = false;
  slot.work = change == Change::topology    ? StageWork::rebuilt
              : change == Change::positions ? StageWork::positions
                                            : StageWork::cached;
  slot.has_result = true;
  slot.source = source;
  slot.settings = s;
  for (size_t j = i + 1; j < slots_.size(); ++j) slots_[j].pending = combined(slots_[j].pending, change);
  return change;
}

int Pipeline::stop(const PipelineSettings& s) const {
  const int last = find(to_string(s.stage));
  if (last < 0)
    throw InvalidInputError(std::string("pipeline: no stage ") + to_string(s.stage) + " in the pipeline");
  return last;
}

int Pipeline::last_on_stage(const PipelineSettings& s) const {
  const int end = stop(s);
  int last = 0;
  for (int i = 1; i <= end; ++i)
    if (slots_[i].stage->is_on(s)) last = i;
  return last;
}

const Mesh& Pipeline::run_stages(int last, const PipelineSettings& s, const PipelineSettings& budgeted,
                                 bool streams_last_level) {
  last_level_.reset();
  warnings_.clear();
  const int end = stop(s);
  for (int i = 0; i <= end; ++i) slots_[i].stage->check(s);
  for (Slot& slot : slots_) slot.work = StageWork::skipped;
  int current = 0;  // the stage whose result the next stage reads
  Change change = Change::none;
  bool is_budget_checked = false;
  // Up to settings.stage for the budget, which counts the computed stages from the mesh they start from
  // (also those a caller streams after `last`); up to `last` for the passes.
  for (int i = 0; i <= end; ++i) {
    PipelineStage& stage = *slots_[i].stage;
    if (!stage.is_editable() && !is_budget_checked) {
      check_budget(slots_[current].stage->result(), budgeted, streams_last_level);
      is_budget_checked = true;
    }
    if (i > last) break;
    if (!stage.is_on(s)) {
      if (stage.free_while_off()) {
        slots_[i].has_result = false;
        forget_lent(slots_[i]);
      }
      continue;
    }
    change = run_stage(i, current, s);
    current = i;
  }
  result_ = current;
  note_result_change(change);
  return slots_[current].stage->result();
}

namespace {

bool has_sharp_edge(const Mesh& mesh) {
  if (mesh.has_sharpness_weights()) return true;
  return std::any_of(mesh.edges().begin(), mesh.edges().end(), [](const Edge& e) { return e.is_sharp; });
}

}  // namespace

// The stages are found in the list by what they are, not by the settings' stage names: a stage added
// after a subdivision or before the offset is then run, not skipped.
LastSubdivision Pipeline::run_to_last_subdivision(const PipelineSettings& s, bool needs_creases) {
  const int last = last_on_stage(s);
  const auto* subdivision = dynamic_cast<const SubdivisionStage*>(slots_[last].stage.get());
  if (!subdivision) return {&run(s), 0};
  const Mesh& input = run_to(last - 1, s, s, true);
  if (!subdivision_outputs_every_face(input, s.boundary) || (needs_creases && has_sharp_edge(input)))
    return {&run(s), 0};
  return {&input, subdivision->levels(s)};
}

const Mesh* Pipeline::run_to_last_offset(const PipelineSettings& s) {
  const int last = last_on_stage(s);
  if (!dynamic_cast<const OffsetStage*>(slots_[last].stage.get())) return nullptr;
  return &run_to(last - 1, s, s, false);
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
  for (Slot& slot : slots_) slot.stage->free_positions_data();
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
  if (result_ >= 0) out = std::move(slots_[result_].stage->result());
  MakeStages make_stages = make_stages_;
  *this = Pipeline(std::move(make_stages));
  return out;
}

bool Pipeline::is_solid_result() const {
  return result_ >= 0 && !slots_[result_].stage->is_editable();
}

bool Pipeline::display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                               int threads) const {
  return is_solid_result() && slots_[result_].stage->display_normals(faces, vertices, threads);
}

bool Pipeline::exchange_result_positions(Buffer<Vec3>& positions) {
  if (!is_solid_result()) return false;
  Mesh& result = slots_[result_].stage->result();
  if (positions.size() != result.num_vertices()) return false;
  result.positions().swap(positions);
  // Every computed stage makes its positions again at the next run that reaches it.
  for (Slot& slot : slots_)
    if (!slot.stage->is_editable()) slot.pending = combined(slot.pending, Change::positions);
  return true;
}

bool Pipeline::lend_result(Mesh& mesh, std::function<Mesh()> copy_back) {
  if (!is_solid_result()) return false;
  Slot& slot = slots_[result_];
  std::swap(slot.stage->result(), mesh);
  slot.is_lent = true;
  slot.copy_back = std::move(copy_back);
  return true;
}

TopologyReport Pipeline::result_report() const {
  if (result_ < 0) return {};
  const Slot& slot = slots_[result_];
  if (is_solid_result())
    if (std::optional<TopologyReport> report =
            slot.stage->derived_report(slots_[slot.source].stage->result()))
      return std::move(*report);
  return topology_report(slot.stage->result());
}

StageWork Pipeline::work(Stage stage) const {
  return work(to_string(stage));
}

StageWork Pipeline::work(std::string_view stage_name) const {
  const int i = find(stage_name);
  return i < 0 ? StageWork::skipped : slots_[i].work;
}

const MergeSummary& Pipeline::merge_summary() const {
  static const MergeSummary none;
  for (const Slot& slot : slots_)
    if (const auto* merge = dynamic_cast<const MergeStage*>(slot.stage.get())) return merge->summary();
  return none;
}

}  // namespace nome
