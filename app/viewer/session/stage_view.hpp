#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "nome/query/triangle_bvh.hpp"
#include "viewer/session/background_job.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

namespace nome::viewer {

// What changed in a session's input since the last request.
struct InputChange {
  Change geometry = Change::none;  // the positions (a slider moved vertices), or the topology (and at first)
  bool face_attributes = false;    // a colour changed (also with every new topology)
  bool operator==(const InputChange&) const = default;
};

// The displayed stage: computed by jobs off the UI thread from the session's polygons and the stage
// settings, shown when the latest one finishes; and the picking BVH of the shown mesh. The one place
// that runs the stage pipeline.
class StageView {
 public:
  // What a job runs: the stage pipeline by default (tests give their own).
  using Evaluate =
      std::function<std::optional<StageResult>(const SceneInput&, const PipelineSettings&, nome::stop_token)>;
  StageView();
  explicit StageView(Evaluate evaluate) : evaluate_(std::move(evaluate)) {}

  PipelineSettings& settings() { return settings_; }
  const PipelineSettings& settings() const { return settings_; }

  // Asks for the stage when the session's polygons or the settings changed since the last request.
  // One job runs at a time: a request made while one is in flight waits, replacing any other waiting,
  // until that one is taken (a slider dragged over a slow stage shows a result every job's time rather
  // than none until it stops). After clear() or invalidate() the request supersedes the one in flight.
  // Returns what changed in the session's input since the last request (nothing when only the settings
  // changed).
  InputChange request(const Session& session);
  // The result of the latest request if it finished within `patience`; throws the pipeline's errors.
  std::optional<StageResult> take(std::chrono::milliseconds patience);
  // The same within a frame: never waits while a stage is shown (it stays up until the new one is
  // ready); a file's first picture waits a little, so that short work shows in the frame that asked.
  std::optional<StageResult> take_for_frame() { return take(std::chrono::milliseconds(shown_ ? 0 : 30)); }
  // Makes the result the shown stage, at time `now` (seconds).
  void show(StageResult result, double now);
  // The next request starts a job even if nothing changed (a new session).
  void invalidate() { has_request_ = false; }
  // A new document: nothing shown until its first result.
  void clear();

  const StageResult* shown() const { return shown_ ? &*shown_ : nullptr; }
  const Mesh* shown_mesh() const { return shown_ ? shown_->mesh.get() : nullptr; }
  bool is_busy() const { return job_.is_busy() || waiting_; }
  double seconds_running() const { return job_.seconds_running(); }
  WorkProgress progress() const { return pipeline_.progress(); }

  // The BVH of the shown mesh, for picks: built off the UI thread once the geometry has rested for a
  // moment (a slider drag never starts one), or at a pick that comes sooner (waiting for a build in
  // flight rather than starting another).
  const TriangleBvh& picking_bvh();
  // Takes a finished BVH build and starts one once the geometry rested; throws the build's errors.
  void prefetch_picking_bvh(double now);

 private:
  void take_picking_bvh(std::chrono::milliseconds patience);

  PipelineSettings settings_ = initial_settings();
  StagePipeline pipeline_;
  Evaluate evaluate_;
  BackgroundJob<std::optional<StageResult>> job_;
  BackgroundJob<std::optional<StageResult>>::Work waiting_;  // the request after the one in flight
  std::uint64_t requested_version_ = 0, requested_topology_version_ = 0, requested_attributes_version_ = 0;
  PipelineSettings requested_settings_;
  bool has_request_ = false;
  std::optional<StageResult> shown_;
  double shown_time_ = 0.0;
  struct PickingBvh {
    std::shared_ptr<const Mesh> mesh;  // what it was built over
    std::shared_ptr<const TriangleBvh> bvh;
  };
  BackgroundJob<PickingBvh> bvh_job_;
  std::shared_ptr<const TriangleBvh> picking_bvh_;  // of shown_, once built
};

}  // namespace nome::viewer
