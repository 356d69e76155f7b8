#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "nome/ops/pipeline.hpp"
#include "nome/query/print_check.hpp"
#include "render/cube_set.hpp"
#include "viewer/session/background_job.hpp"
#include "viewer/session/scene_input_feed.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_view.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The check's own pipeline, its runs serialised (a superseded check may still be running).
struct CheckPipeline {
  std::mutex mutex;
  Pipeline pipeline;
  SceneInputFeed feed;
};

// One finished print check, and what it was run on.
struct PrintCheckRun {
  std::uint64_t version = 0;    // the session's polygons
  PipelineSettings settings;    // the stage settings (the stage itself ignored)
  double requested_wall = 0.0;  // 0: 2 x the offset distance
  std::shared_ptr<const Mesh> surface;
  PrintCheck check;
  double seconds = 0.0;
};

// The viewer's print check: checks the surface the offset thickens (the subdivided stage, with
// the stage settings' offset distance) off the UI thread, on demand or once the geometry has rested after a
// change, and tells the window which faces of the shown stage to paint and where the places are.
class PrintCheckView {
 public:
  bool is_automatic = true;  // check again after each change, once the geometry rests
  double min_wall = 0.0;     // 0: 2 x the offset distance

  // Starts a check of the session's polygons under `settings` now (a newer request supersedes one in flight).
  void request(const Session& session, const PipelineSettings& settings);
  // Once a frame: takes a finished check (true when one arrived; rethrows its errors) and, when automatic
  // and an offset stage is shown, starts one after the polygons, the settings or the wall changed and no
  // stage has been computed for `rest_seconds`.
  bool update(StageView& stage, const Session& session, double now);
  void clear();

  bool is_busy() const { return job_.is_busy(); }
  double seconds_running() const { return job_.seconds_running(); }
  double progress() const;
  const PrintCheckRun* last() const { return last_ ? &*last_ : nullptr; }
  // Whether the last check was of these polygons and settings.
  bool is_current(const Session& session, const PipelineSettings& settings) const;

  // The shown stage's faces made from faces the check found (red: crossings; magenta: fold-overs; orange:
  // at a vertex too close to another sheet); none when the shown stage is not numbered from the checked
  // surface (the scene before its subdivision) or the check is out of date.
  std::vector<FacePaint> face_paints(const StageResult& shown, const PipelineSettings& settings) const;
  // A cube at each place, in its kind's colour.
  std::vector<render::CubeMarker> markers() const;
  // Eight corners of a box around place i, to frame it with the camera.
  std::array<Vec3, 8> place_box(std::size_t place) const;
  // The place the next `next-print-place` frames, cycling through the list.
  std::size_t next_place();

  static constexpr double rest_seconds = 0.5;

 private:
  // The last check is of what update() last saw: its marks belong on the screen.
  bool is_fresh() const {
    return last_ && last_->version == seen_version_ && last_->settings == seen_settings_ &&
           last_->requested_wall == seen_wall_;
  }

  std::shared_ptr<CheckPipeline> pipeline_ = std::make_shared<CheckPipeline>();
  BackgroundJob<std::optional<PrintCheckRun>> job_;
  std::optional<PrintCheckRun> last_;
  // What the automatic check last saw: it starts when this changes.
  std::uint64_t seen_version_ = 0;
  PipelineSettings seen_settings_;
  double seen_wall_ = -1.0;
  double changed_at_ = 0.0;
  bool is_seen_checked_ = false;
  std::size_t next_place_ = 0;
  struct SharedProgress {
    std::mutex mutex;
    double fraction = 0.0;
  };
  std::shared_ptr<SharedProgress> progress_ = std::make_shared<SharedProgress>();
};

// The checked surface's face f as ranges [first, end) of faces of the shown stage: the surface itself,
// its offset (positive copies, then negative ones) and that offset subdivided `levels_after` times (a
// face's children are consecutive). Empty when `shown` is not one of those stages of `surface`.
std::vector<std::array<Index, 2>> shown_faces_of(const Mesh& surface, Index f, Stage stage, int levels_after,
                                                 const Mesh& shown);

}  // namespace nome::viewer
