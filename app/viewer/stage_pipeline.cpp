#include "viewer/stage_pipeline.hpp"

#include <chrono>

namespace nome::viewer {

std::optional<StageResult> StagePipeline::run(const PolygonSoup& scene, const StageSettings&,
                                              std::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  StageResult result;
  Mesh mesh = build_mesh(scene);
  if (stop.stop_requested()) return std::nullopt;
  result.display = render::build_display_data(mesh);
  result.bvh = std::make_shared<const TriangleBvh>(mesh);
  result.borders = std::make_shared<const BorderLookup>(mesh);
  result.mesh = std::make_shared<const Mesh>(std::move(mesh));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace nome::viewer
