#include "viewer/session/stage_view.hpp"

#include <utility>

namespace nome::viewer {

StageView::StageView()
    : evaluate_([this](const SceneInput& input, const PipelineSettings& settings, nome::stop_token stop) {
        return pipeline_.run(input, settings, stop);
      }) {}

InputChange StageView::request(const Session& session) {
  const bool is_new_version = !has_request_ || session.version() != requested_version_;
  if (!is_new_version && settings_ == requested_settings_) return {};
  const bool supersedes = !has_request_;
  InputChange change;
  change.geometry = !has_request_ || session.topology_version() != requested_topology_version_
                        ? Change::topology
                    : is_new_version ? Change::positions
                                     : Change::none;
  change.face_attributes = !has_request_ || session.attributes_version() != requested_attributes_version_;
  requested_version_ = session.version();
  requested_topology_version_ = session.topology_version();
  requested_attributes_version_ = session.attributes_version();
  requested_settings_ = settings_;
  has_request_ = true;
  // The job shares the session's polygons and positions; a slider that moved vertices sends positions.
  waiting_ = [this, input = session.scene_input(), parts = session.face_parts(),
              settings = settings_](nome::stop_token stop) {
    auto result = evaluate_(input, settings, stop);
    if (result) result->parts = parts;
    return result;
  };
  if (supersedes || !job_.is_busy()) job_.submit(std::exchange(waiting_, nullptr));
  return change;
}

std::optional<StageResult> StageView::take(std::chrono::milliseconds patience) {
  auto result = job_.take(patience);
  if (waiting_ && !job_.is_busy()) job_.submit(std::exchange(waiting_, nullptr));
  if (result && *result) return std::move(**result);
  return std::nullopt;
}

void StageView::show(StageResult result, double now) {
  picking_bvh_.reset();
  shown_time_ = now;
  shown_ = std::move(result);
}

void StageView::clear() {
  shown_.reset();
  picking_bvh_.reset();
  has_request_ = false;
  waiting_ = nullptr;
}

const TriangleBvh& StageView::picking_bvh() {
  if (!picking_bvh_ && bvh_job_.is_busy()) take_picking_bvh(std::chrono::minutes(1));
  if (!picking_bvh_) picking_bvh_ = std::make_shared<const TriangleBvh>(*shown_mesh());
  return *picking_bvh_;
}

void StageView::prefetch_picking_bvh(double now) {
  take_picking_bvh(std::chrono::milliseconds(0));
  constexpr double rest_seconds = 0.25;
  if (!shown_ || picking_bvh_ || job_.is_busy() || bvh_job_.is_busy() || now - shown_time_ < rest_seconds)
    return;
  bvh_job_.submit([mesh = shown_->mesh](nome::stop_token) {
    return PickingBvh{mesh, std::make_shared<const TriangleBvh>(*mesh)};
  });
}

void StageView::take_picking_bvh(std::chrono::milliseconds patience) {
  // A BVH of a mesh no longer shown is dropped.
  if (auto done = bvh_job_.take(patience); done && shown_ && done->mesh == shown_->mesh)
    picking_bvh_ = done->bvh;
}

}  // namespace nome::viewer
