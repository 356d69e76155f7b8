#include "viewer/stage_pipeline.hpp"

#include <chrono>

#include "nome/ops/merge.hpp"

namespace nome::viewer {

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::scene:
      return "scene";
    case Stage::merged:
      return "merged";
  }
  return "scene";
}

std::optional<StageResult> StagePipeline::run(const PolygonSoup& scene, const StageSettings& settings,
                                              std::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  StageResult result;
  Mesh mesh = build_mesh(scene);
  if (settings.stage != Stage::scene) {
    MergeOptions options;
    options.tolerance = settings.merge_tolerance;
    MergeResult merged = merge_boundaries(mesh, options);
    for (const SkippedMerge& skip : merged.skipped) result.warnings.push_back("merge: " + skip.message);
    result.notes.push_back("merged " + std::to_string(merged.glued_edges) + " edge pairs (tolerance " +
                           std::to_string(merged.tolerance) + ")");
    mesh = std::move(merged.mesh);
  }
  if (stop.stop_requested()) return std::nullopt;
  result.display = render::build_display_data(mesh);
  result.bvh = std::make_shared<const TriangleBvh>(mesh);
  result.borders = std::make_shared<const BorderLookup>(mesh);
  result.mesh = std::make_shared<const Mesh>(std::move(mesh));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace nome::viewer
