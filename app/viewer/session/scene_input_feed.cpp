#include "viewer/session/scene_input_feed.hpp"

namespace nome::viewer {

void SceneInputFeed::feed(Pipeline& pipeline, const SceneInput& input) {
  if (version_ != input.topology_version) {
    forget();  // until the pipeline has taken it
    PipelineInput next = *input.polygons;
    next.soup.positions = *input.positions;
    if (input.face_attributes) next.soup.face_attributes = *input.face_attributes;
    pipeline.replace_input(std::move(next));
    version_ = input.topology_version;
  } else {
    if (face_attributes_ != input.face_attributes && input.face_attributes)
      pipeline.set_input_face_attributes(*input.face_attributes);
    if (positions_ != input.positions) pipeline.move_input_vertices(*input.positions);
  }
  positions_ = input.positions;
  face_attributes_ = input.face_attributes;
}

}  // namespace nome::viewer
