#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/mesh/quad_surface.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/change.hpp"
#include "nome/ops/merge.hpp"
#include "nome/ops/offset_surface.hpp"
#include "nome/ops/pipeline_input.hpp"
#include "nome/ops/pipeline_settings.hpp"
#include "nome/ops/pipeline_stage.hpp"
#include "nome/progress.hpp"

namespace nome {

// The size of a pipeline's result, estimated from counts before anything is computed.
struct PipelineEstimate {
  double faces = 0;  // of the final result
  double bytes = 0;  // every cached stage together
};

// The estimate for the stages after the merge, from the mesh they start from. `streams_last_level`: the
// last stage, a subdivision, is kept as quads (Pipeline::run_surface), not as a Mesh.
PipelineEstimate estimate_pipeline(const Mesh& input, const PipelineSettings& settings,
                                   bool streams_last_level = false);

// What a stage did in the last run.
enum class StageWork { skipped, cached, positions, rebuilt };

// What the merge stage did, for the caller to tell.
struct MergeSummary {
  Index glued_edges = 0;  // pairs of boundary edges that became one edge
  double tolerance = 0;   // the absolute tolerance used
  std::vector<SkippedMerge> skipped;
};

// The input of the settings' last stage when that stage is a subdivision whose every face is output (no
// holes, no border dropped by BoundaryMode::none), with its level count; otherwise the whole result with
// levels = 0.
struct LastSubdivision {
  const Mesh* input = nullptr;
  int levels = 0;
};

// The result of Pipeline::run_surface: the last subdivision's quads, the offset solid as it is written,
// or the Mesh when neither can stand for it.
struct PipelineSurface {
  const Mesh* mesh = nullptr;
  std::optional<QuadSurface> quads;
  std::optional<OffsetSurface> solid;
};

class SceneStage;

// Makes the stages a pipeline runs, in order; the first is the scene stage (as builtin_stages makes it).
using MakeStages = std::function<std::vector<std::unique_ptr<PipelineStage>>()>;

// The whole way from a scene's polygons to a printable solid: an ordered list of stages (PipelineStage;
// builtin_stages: scene -> merged -> subdivided -> offset -> subdivided offset), each stage's result cached.
// A run goes down the list to the stage the settings ask for. Each stage passes on what changed in its
// result (Change), and the stages after it take it up when a run reaches them. A run redoes only what
// changed: an input whose polygons are the same as last time (a slider that moves vertices) flows its
// positions through the stages' positions passes and builds no mesh; a new topology runs the topology
// passes from the first stage it reaches; other settings re-run only the stages they touch (another offset
// distance keeps the subdivision).
class Pipeline {
 public:
  Pipeline();
  // A pipeline of other stages (builtin_stages with a stage added). Throws InvalidInputError when the
  // first is not the scene stage.
  explicit Pipeline(MakeStages make_stages);
  ~Pipeline();
  Pipeline(Pipeline&&) noexcept;
  Pipeline& operator=(Pipeline&&) noexcept;

  // The polygons of the scene stage: makes the scene mesh, or only moves its vertices when the polygons
  // are those of the last input. Throws TopologyError naming the input part at fault.
  void set_input(PipelineInput input);
  // The polygons of the scene stage from a caller that knows they are a new topology (the viewer's
  // document tells it): builds the scene mesh without comparing them with the last input.
  void replace_input(PipelineInput input);
  // The scene stage as a mesh the caller built (compared with the last one).
  void set_input(const Mesh& scene_mesh);
  // New face attributes (colours) for the last input's faces: every stage carries them at its next run,
  // through the positions pass (no rebuild). Throws InvalidInputError without an input or for more
  // values than faces.
  void set_input_face_attributes(Attributes faces);
  // New positions for the vertices of the last set_input(PipelineInput), its polygons unchanged (a slider
  // that moved vertices: Scene::combined_positions): no comparison, no copy of its polygons. Throws
  // InvalidInputError when the count differs or there was no such input.
  void move_input_vertices(Buffer<Vec3> positions);

  // Makes settings.stage from the input and returns it (valid until the next run or input): runs the list
  // down to the stage named to_string(settings.stage). Throws InvalidInputError for settings out of range
  // or a stage not in the list, and BudgetError, with the estimate, when the result would exceed the
  // memory budget unless forced.
  const Mesh& run(const PipelineSettings& settings);
  // The same, with the scene mesh given (set_input, then run).
  const Mesh& run(const Mesh& scene_mesh, const PipelineSettings& settings);
  // Runs the stages before the last subdivision (see LastSubdivision), checking the budget of the whole
  // run with that level as quads. `needs_creases`: the caller reads the result's sharp edges, so a last
  // level that would have some is run as a Mesh.
  LastSubdivision run_to_last_subdivision(const PipelineSettings& settings, bool needs_creases = false);
  // When the settings' last stage is an offset with no levels after it: runs the stages before it and
  // returns the offset's input (valid until the next run); otherwise runs nothing and returns null.
  const Mesh* run_to_last_offset(const PipelineSettings& settings);
  // The normals the offset of `input` (run_to_last_offset's) moves its vertices along, computed on up to
  // `threads` threads; a warning naming its degenerate faces and vertices joins warnings().
  Normals offset_normals(const Mesh& input, int threads);
  // Runs the stages run_surface(settings, needs_creases) reuses, all but the one it may stream, so that a
  // caller can report their warnings and budget errors before writing.
  void run_before_surface(const PipelineSettings& settings, bool needs_creases = false);
  // The result of run() for a writer, with the same positions and polygons in the same order as run()'s
  // Mesh: the last subdivision level as quads straight from its Refinement (about a fifth of the memory);
  // an offset with no levels after it as an OffsetSurface (its input's vertex normals, nothing stored
  // per face); otherwise run()'s Mesh. Valid until the next run. `needs_creases` as for
  // run_to_last_subdivision. Before an offset it frees the subdivisions' refinements: a later run keeps
  // their results while nothing changes, and rebuilds them for moved vertices.
  PipelineSurface run_surface(const PipelineSettings& settings, bool needs_creases = false);
  // Moves the last result out (for a one-shot caller such as the command line); the caches start over.
  Mesh take_result();

  // Where the stages that rebuild a mesh (subdivision, offset) report how far they got.
  void set_progress(Progress progress);

  // The normals a display draws the last run's result with when the kernel has them already: an offset
  // of two parallel copies (offset_packed_normals), else false (the caller computes them).
  bool display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices, int threads = 1) const;
  // Swaps the last run's result positions with `positions` when the result is a subdivision's or an
  // offset's and `positions` has as many: a caller that keeps each result (a viewer's slider) then takes
  // them without copying, and hands back an older array to be written over. The stages compute their
  // positions again at the next run, whatever changed. Otherwise returns false and changes nothing.
  bool exchange_result_positions(Buffer<Vec3>& positions);

  // Lends the last run's result, when it is a subdivision's or an offset's, to a caller that keeps it (a
  // viewer shows it without copying it first): swapped with `mesh`. A later run that takes the stage's
  // result up again (moved vertices, the same topology) calls `copy_back` for a copy of it, positions and
  // all; one that makes the stage anew does not call it. Runs that leave the stage out keep it lent (a
  // result shown before another stage's, taken back when that stage is shown again), so several stages
  // may be lent at once. Without `copy_back` the next run that reaches the stage makes its result again.
  // Otherwise returns false and changes nothing.
  bool lend_result(Mesh& mesh, std::function<Mesh()> copy_back);
  // The last run's topology report: from its last stage's input where that stage decides it (an offset,
  // a subdivision that outputs every face; subdivided_topology_report, offset_topology_report), else
  // counted on the result (then before lending it).
  TopologyReport result_report() const;

  // What the last run changed in its result since the run before, and the version of the result's
  // topology, which grows with every run whose result has other connectivity than the last one's (a stage
  // rebuilt, or another stage's mesh is the result). A display keeps what it derived from the connectivity
  // while the version stays.
  Change result_change() const { return result_change_; }
  std::uint64_t result_topology_version() const { return result_topology_version_; }

  // What each stage did in the last run (skipped: the run did not reach it, or it was off).
  StageWork work(Stage stage) const;
  StageWork work(std::string_view stage_name) const;
  const MergeSummary& merge_summary() const;
  // Warnings of the last run's new work: edges joining no faces, merges skipped, degenerate faces met by
  // the offset's normals.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  // A stage and the cache around it.
  struct Slot {
    std::unique_ptr<PipelineStage> stage;
    // What changed in the stage's input since its last pass (the stages a run skips catch up at the next
    // run that reaches them).
    Change pending = Change::topology;
    // The input's face attributes changed since the stage last carried them (a positions pass keeps them).
    bool attributes_pending = true;
    bool has_result = false;
    int source = -1;            // the stage whose result was the input of its last pass
    PipelineSettings settings;  // of its last pass
    StageWork work = StageWork::skipped;
    // The result is lent out (lend_result) and not taken back; it stays lent while runs leave the stage
    // out, so a stage turned off and on again takes it back instead of reading the empty mesh left here.
    bool is_lent = false;
    std::function<Mesh()> copy_back;
  };

  SceneStage& scene();
  // The index of the stage of that name in the list, or -1.
  int find(std::string_view stage_name) const;
  // Runs stage `i` on the result of stage `source` with the pass its change needs; returns what changed
  // in its result, which the stages after it take up.
  Change run_stage(int i, int source, const PipelineSettings& settings);
  // Whether the slot's lent result can be taken up again: copied back (true), or to be made anew.
  static bool takes_back(Slot& slot);
  // The slot's result is made anew or freed: a copy of the lent one is not needed.
  static void forget_lent(Slot& slot);
  void input_changed(Change change);
  // The index of settings.stage in the list; throws InvalidInputError when it is not there.
  int stop(const PipelineSettings& settings) const;
  // The last stage up to settings.stage that is on (its result is run()'s), or 0, the scene.
  int last_on_stage(const PipelineSettings& settings) const;
  // Runs the list down to stage `last` (at most settings.stage's), checking every stage settings.stage
  // runs through.
  const Mesh& run_stages(int last, const PipelineSettings& settings, const PipelineSettings& budgeted,
                         bool streams_last_level);
  // Sets result_change() to what the stages that made the result changed, or to a new topology when
  // the result is another stage's mesh than last time.
  void note_result_change(Change change);
  // Whether the last result is the solid stages' (not the scene's or merge's mesh).
  bool is_solid_result() const;
  // run(), with the budget checked for `budgeted` (the last level as quads when `streams_last_level`).
  const Mesh& run(const PipelineSettings& settings, const PipelineSettings& budgeted,
                  bool streams_last_level);
  // run_stages, the caches started over for the stages that threw.
  const Mesh& run_to(int last, const PipelineSettings& settings, const PipelineSettings& budgeted,
                     bool streams_last_level);
  // run_surface's offset of `input` (run_to_last_offset's).
  PipelineSurface run_offset_surface(const Mesh& input, const PipelineSettings& settings, bool needs_creases);

  MakeStages make_stages_;
  std::vector<Slot> slots_;
  int result_ = -1;       // the stage whose result the last run returned
  int last_result_ = -1;  // the stage whose result the run before last returned
  Change result_change_ = Change::topology;
  std::uint64_t result_topology_version_ = 0;
  std::optional<Refinement> last_level_;  // run_surface's: the last level's quads and positions
  Progress progress_;
  std::vector<std::string> warnings_;
};

}  // namespace nome
