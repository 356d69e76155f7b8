#include "viewer/stage_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace nome::viewer {

PipelineSettings initial_settings() {
  PipelineSettings s;
  s.stage = Stage::scene;
  s.should_merge = true;
  s.subdivision_levels = 2;
  s.offset_distance = 0.05;
  s.subdivision_after = 1;
  s.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  return s;
}

StagePipeline::StagePipeline() {
  pipeline_.set_progress({[this](std::string_view task, double fraction) {
    std::lock_guard lock(progress_mutex_);
    progress_ = {std::string(task), fraction};
  }});
}

WorkProgress StagePipeline::progress() const {
  std::lock_guard lock(progress_mutex_);
  return progress_;
}

std::optional<StageResult> StagePipeline::run(const PipelineInput& input, const PipelineSettings& settings,
                                              std::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  {
    std::lock_guard progress_lock(progress_mutex_);
    progress_ = {};
  }
  const auto start = std::chrono::steady_clock::now();
  StageResult result;
  result.stage = settings.stage;
  pipeline_.set_input(input);
  // The window keeps the result while the pipeline's caches change in the next run: a copy.
  Mesh mesh = pipeline_.run(settings);
  result.warnings = pipeline_.warnings();
  // Told once, where the merge is what the user asked to see (not again at each later stage's run).
  if (settings.stage == Stage::merged && pipeline_.work(Stage::merged) != StageWork::cached)
    result.notes.push_back("merged " + std::to_string(pipeline_.merge_summary().glued_edges) +
                           " edge pairs (tolerance " + std::to_string(pipeline_.merge_summary().tolerance) +
                           ")");
  if (stop.stop_requested()) return std::nullopt;
  result.display = render::build_display_data(mesh);
  result.borders = std::make_shared<const BorderLookup>(mesh);
  result.topology = topology_report(mesh);
  result.mesh = std::make_shared<const Mesh>(std::move(mesh));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace nome::viewer
