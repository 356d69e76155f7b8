#pragma once

#include <atomic>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include "nome/stop_token.hpp"

#include "nome/edit/scene_document.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/query/border_lookup.hpp"
#include "render/mesh_display_data.hpp"
#include "viewer/session/scene_input_feed.hpp"
#include "viewer/session/session.hpp"

namespace nome::viewer {

// The control panel's first settings: the scene on screen, and what the later stages would make of it.
PipelineSettings initial_settings();

// Everything a frame needs of a new displayed mesh, computed off the UI thread: the mesh, its GPU-ready
// arrays, its borders and its topology report. Only the upload to GL is left to the UI thread, and the
// picking BVH to the first pick (a slider drag shows many meshes and picks on none).
struct StageResult {
  Stage stage = Stage::scene;  // which stage the mesh is
  bool is_smoothed = false;    // a subdivision surface (automatic shading draws it smooth)
  std::shared_ptr<const Mesh> mesh;
  render::MeshDisplayData display;
  std::shared_ptr<const BorderLookup> borders;
  TopologyReport topology;
  std::vector<std::string> warnings;
  std::vector<std::string> notes;  // what the stages did, for the log
  FaceParts parts;                 // of the input it was made from (faces keep their order)
  double seconds = 0.0;
};

// What a run in flight is doing: the kernel's task ("subdivision", "offset") and how far it got (0..1).
struct WorkProgress {
  std::string task;
  double fraction = 0.0;
};

// The kernel's Pipeline behind the window's background jobs: runs are serialised, and a run whose stop
// was requested before it began, or before its display data, gives up and returns none. The pipeline's
// caches outlive a run: a slider that only moves vertices builds no mesh, and its result shares the last
// one's display topology, borders and topology report (the renderer then updates positions only), its
// mesh and display positions arrays no longer held elsewhere taking the new ones (no fresh pages; the
// mesh's positions change places with the pipeline's, Pipeline::exchange_result_positions). A new
// topology's result holds the pipeline's own mesh (Pipeline::lend_result): the frame does not wait for a
// copy, which is made after the result is handed over, and read by the pipeline only when a later run
// takes the result up again (a run that makes a new topology does not wait for it).
class StagePipeline {
 public:
  StagePipeline();

  // Throws the kernel's errors (TopologyError naming the elements, BudgetError). An input of a topology
  // version the pipeline has taken already only moves its vertices (Pipeline::move_input_vertices), or
  // changes nothing when its positions are the last ones.
  std::optional<StageResult> run(const SceneInput& input, const PipelineSettings& settings,
                                 nome::stop_token stop);
  // The same for an input that comes with no version (tests, benches): compared with the last one
  // (Pipeline::set_input).
  std::optional<StageResult> run(const PipelineInput& input, const PipelineSettings& settings,
                                 nome::stop_token stop);
  // The progress of the run in flight (an empty task before the first report), for the status overlay.
  WorkProgress progress() const;

 private:
  std::optional<StageResult> run_stages(const PipelineSettings& settings, nome::stop_token stop);
  // The display arrays: a result of the last one's topology (the pipeline's result_topology_version)
  // takes over its shared parts.
  void display(const Mesh& mesh, const PipelineSettings& settings, StageResult& result);
  // The result's mesh for a result of the last one's topology: a kept copy no one else holds, with the
  // pipeline's positions, or null when all are held. Valid only after the display arrays: the pipeline's
  // result then holds an older array.
  std::shared_ptr<const Mesh> kept_copy(const Mesh& mesh);
  std::shared_ptr<const Mesh> new_copy(const Mesh& mesh);
  std::shared_ptr<const render::DisplayPositions> display_positions(const Mesh& mesh,
                                                                    const render::DisplayTopology& topology,
                                                                    int threads);

  std::mutex mutex_;
  // Copies the result lent to the last new topology's StageResult; done once the flag is set.
  nome::jthread copy_thread_;
  std::shared_ptr<std::atomic<bool>> copy_done_;
  SceneInputFeed feed_;
  // What results of the last one's topology share.
  struct Shared {
    std::shared_ptr<const render::DisplayTopology> display;
    std::shared_ptr<const BorderLookup> borders;
    TopologyReport topology;
    std::uint64_t version = 0;  // the pipeline's result_topology_version
  };
  std::optional<Shared> last_;
  std::vector<std::shared_ptr<Mesh>> copies_;  // of the last topology, handed out in results
  std::vector<std::shared_ptr<render::DisplayPositions>> positions_;  // likewise
  mutable std::mutex progress_mutex_;
  WorkProgress progress_;
  Pipeline pipeline_;
};

}  // namespace nome::viewer
