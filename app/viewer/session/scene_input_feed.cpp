#include "viewer/session/scene_input_feed.hpp"

namespace nome::viewer {

void SceneInputFeed::feed(Pipeline& pipeline, const SceneInput& input) {
  if (version_ != input.topology_version) {
    forget();  // until the pipeline has taken it
    PipelineInput next = *input.polygons;
    next.soup.positions = *input.positions;
    pipeline.replace_input(std::move(next));
    version_ = input.topology_version;
  } else if (positions_ != input.positions) {
    pipeline.move_input_vertices(*input.positions);
  }
  positions_ = input.positions;
}

}  // namespace nome::viewer
