#include "viewer/stage_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include "nome/ops/merge.hpp"

namespace nome::viewer {

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::scene:
      return "scene";
    case Stage::merged:
      return "merged";
    case Stage::subdivided:
      return "subdivided";
    case Stage::offset:
      return "offset";
    case Stage::subdivided_offset:
      return "subdivided offset";
  }
  return "scene";
}

bool is_editable(Stage stage) {
  return stage == Stage::scene || stage == Stage::merged;
}

namespace {

PipelineOptions pipeline_options(const StageSettings& s) {
  PipelineOptions o;
  o.subdivision_levels = s.subdivision_levels;
  o.rule = s.rule;
  o.offset_distance =
      s.stage == Stage::offset || s.stage == Stage::subdivided_offset ? s.offset_distance : 0.0;
  o.subdivision_after = s.stage == Stage::subdivided_offset ? s.subdivision_after : 0;
  o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  return o;
}

}  // namespace

std::optional<StageResult> StagePipeline::run(const PolygonSoup& scene, const StageSettings& settings,
                                              std::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  StageResult result;
  result.stage = settings.stage;
  Mesh mesh = build_mesh(scene);
  if (settings.stage == Stage::merged || (!is_editable(settings.stage) && settings.subdivide_merged)) {
    MergeOptions options;
    options.tolerance = settings.merge_tolerance;
    MergeResult merged = merge_boundaries(mesh, options);
    for (const SkippedMerge& skip : merged.skipped) result.warnings.push_back("merge: " + skip.message);
    // Told once, where the merge is what the user asked to see (not again at each later stage's run).
    if (settings.stage == Stage::merged)
      result.notes.push_back("merged " + std::to_string(merged.glued_edges) + " edge pairs (tolerance " +
                             std::to_string(merged.tolerance) + ")");
    mesh = std::move(merged.mesh);
  }
  if (stop.stop_requested()) return std::nullopt;
  if (!is_editable(settings.stage)) {
    // The window keeps the result while the pipeline's caches change in the next run: a copy.
    mesh = pipeline_.run(mesh, pipeline_options(settings));
    for (const std::string& w : pipeline_.warnings()) result.warnings.push_back(w);
  }
  if (stop.stop_requested()) return std::nullopt;
  result.display = render::build_display_data(mesh);
  result.borders = std::make_shared<const BorderLookup>(mesh);
  result.topology = topology_report(mesh);
  result.mesh = std::make_shared<const Mesh>(std::move(mesh));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace nome::viewer
