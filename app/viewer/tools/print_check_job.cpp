#include "viewer/tools/print_check_job.hpp"

#include <algorithm>
#include <chrono>

#include "render/bounding_box.hpp"

namespace nome::viewer {
namespace {

// The settings that decide the checked surface and its offset; the stage shown and the levels after the
// offset do not.
PipelineSettings checked_settings(PipelineSettings settings) {
  settings.stage = Stage::subdivided_offset;
  settings.subdivision_after = 0;
  return settings;
}

// A copy of the surface the offset thickens (the subdivided stage) for these settings, from the check's
// own pipeline: running the stage pipeline to another stage would drop the offset it caches for the next
// slider move. None when a newer check was asked for before it began.
std::shared_ptr<const Mesh> surface_to_check(CheckPipeline& check, const SceneInput& input,
                                             const PipelineSettings& settings, nome::stop_token stop) {
  std::lock_guard lock(check.mutex);
  if (stop.stop_requested()) return nullptr;
  PipelineSettings surface = settings;
  surface.stage = Stage::subdivided;
  check.feed.feed(check.pipeline, input);
  return std::make_shared<const Mesh>(check.pipeline.run(surface));
}

// Thrown from the check's progress to give up once a newer request superseded it.
struct Superseded {};

constexpr std::array<std::uint8_t, 4> crossing_color{230, 20, 20, 255};
constexpr std::array<std::uint8_t, 4> fold_over_color{215, 0, 215, 255};
constexpr std::array<std::uint8_t, 4> near_miss_color{255, 140, 0, 255};

glm::vec3 marker_color(FindingKind kind) {
  switch (kind) {
    case FindingKind::fold_over:
      return {0.85f, 0.0f, 0.85f};
    case FindingKind::near_miss:
      return {1.0f, 0.55f, 0.0f};
    case FindingKind::crossing:
      break;
  }
  return {0.9f, 0.05f, 0.05f};
}

double diagonal(const Mesh& mesh) {
  const render::BoundingBox box = render::BoundingBox::of(mesh.positions());
  return box.is_empty() ? 0.0 : glm::distance(box.min, box.max);
}

}  // namespace

std::vector<std::array<Index, 2>> shown_faces_of(const Mesh& surface, Index f, Stage stage, int levels_after,
                                                 const Mesh& shown) {
  const Index faces = surface.num_faces();
  if (!is_solid(stage)) {
    if (shown.num_faces() != faces) return {};
    return {{f, f + 1}};
  }
  std::uint64_t first = f, end = f + 1, other = faces + f, other_end = faces + f + 1;
  if (stage == Stage::subdivided_offset && levels_after > 0) {
    // Level 1: the children of offset face g are its corners; each later level makes 4 of each quad.
    const std::uint64_t scale = std::uint64_t(1) << (2 * (levels_after - 1));
    const std::uint64_t corner = surface.face_first_corner(f), degree = surface.face_degree(f);
    first = corner * scale;
    end = (corner + degree) * scale;
    other = (surface.num_corners() + corner) * scale;
    other_end = (surface.num_corners() + corner + degree) * scale;
  }
  if (other_end > shown.num_faces()) return {};
  return {{Index(first), Index(end)}, {Index(other), Index(other_end)}};
}

void PrintCheckView::request(const Session& session, const PipelineSettings& settings) {
  {
    std::lock_guard lock(progress_->mutex);
    progress_->fraction = 0.0;
  }
  job_.submit([pipeline = pipeline_, input = session.scene_input(), version = session.version(),
               settings = checked_settings(settings), wall = min_wall,
               progress = progress_](nome::stop_token stop) -> std::optional<PrintCheckRun> {
    const auto start = std::chrono::steady_clock::now();
    PrintCheckRun run{version, settings, wall, surface_to_check(*pipeline, input, settings, stop), {}, 0.0};
    if (!run.surface) return std::nullopt;
    PrintCheckOptions options;
    options.offset_distance = settings.offset_distance;
    options.min_wall = wall;
    options.threads = settings.threads;
    options.progress = {[stop, progress](std::string_view, double fraction) {
      if (stop.stop_requested()) throw Superseded{};
      std::lock_guard lock(progress->mutex);
      progress->fraction = fraction;
    }};
    try {
      run.check = check_printability(*run.surface, options);
    } catch (const Superseded&) {
      return std::nullopt;
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return run;
  });
  seen_version_ = session.version();
  seen_settings_ = checked_settings(settings);
  seen_wall_ = min_wall;
  is_seen_checked_ = true;
}

bool PrintCheckView::update(StageView& stage, const Session& session, double now) {
  bool has_arrived = false;
  if (auto done = job_.take(); done && *done) {
    last_ = std::move(**done);
    next_place_ = 0;
    has_arrived = true;
  }
  const PipelineSettings settings = checked_settings(stage.settings());
  if (session.version() != seen_version_ || !(settings == seen_settings_) || min_wall != seen_wall_) {
    seen_version_ = session.version();
    seen_settings_ = settings;
    seen_wall_ = min_wall;
    changed_at_ = now;
    is_seen_checked_ = false;
  }
  if (stage.is_busy()) changed_at_ = now;
  // Automatic checks follow the offset stages only: a scene looked at before its offset is not subdivided
  // in the background for a check nobody asked for.
  const bool is_offset_shown = is_solid(stage.settings().stage);
  if (is_automatic && is_offset_shown && !is_seen_checked_ && now - changed_at_ >= rest_seconds)
    request(session, stage.settings());
  return has_arrived;
}

void PrintCheckView::clear() {
  job_.cancel();
  last_.reset();
  is_seen_checked_ = false;
  seen_wall_ = -1.0;
}

double PrintCheckView::progress() const {
  std::lock_guard lock(progress_->mutex);
  return progress_->fraction;
}

bool PrintCheckView::is_current(const Session& session, const PipelineSettings& settings) const {
  return last_ && last_->version == session.version() && last_->settings == checked_settings(settings) &&
         last_->requested_wall == min_wall;
}

std::vector<FacePaint> PrintCheckView::face_paints(const StageResult& shown,
                                                   const PipelineSettings& settings) const {
  std::vector<FacePaint> paints;
  if (!is_fresh() || !(last_->settings == checked_settings(settings))) return paints;
  const Mesh& surface = *last_->surface;
  const PrintCheck& check = last_->check;
  auto paint = [&](Index f, const std::array<std::uint8_t, 4>& color) {
    for (const auto& [first, end] :
         shown_faces_of(surface, f, shown.stage, settings.subdivision_after, *shown.mesh))
      for (Index g = first; g < end; ++g) paints.push_back({g, color});
  };
  for (const NearMiss& miss : check.near_misses)
    for (const Index c : surface.vertex_corners(miss.vertex)) paint(surface.corner_face(c), near_miss_color);
  for (const Index f : check.crossings.faces) paint(f, crossing_color);
  for (const Index f : check.fold_over_faces) paint(f, fold_over_color);
  return paints;
}

std::vector<render::CubeMarker> PrintCheckView::markers() const {
  std::vector<render::CubeMarker> cubes;
  if (!is_fresh()) return cubes;
  // Large enough to stand out of the slab around the surface, and never large beside the model.
  const double size = diagonal(*last_->surface);
  const float half = float(std::min(std::max(1.2 * last_->check.offset_distance, 0.01 * size), 0.03 * size));
  for (const PrintPlace& place : last_->check.places)
    cubes.push_back({glm::vec3(place.position), half, marker_color(place.kind)});
  return cubes;
}

std::array<Vec3, 8> PrintCheckView::place_box(std::size_t place) const {
  const PrintPlace& p = last_->check.places.at(place);
  const double half = std::max(4.0 * last_->check.min_wall, 0.05 * diagonal(*last_->surface));
  std::array<Vec3, 8> corners;
  for (int i = 0; i < 8; ++i)
    corners[std::size_t(i)] =
        p.position + half * Vec3(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  return corners;
}

std::size_t PrintCheckView::next_place() {
  const std::size_t place = next_place_;
  next_place_ = (next_place_ + 1) % std::max<std::size_t>(1, last_ ? last_->check.places.size() : 1);
  return place;
}

}  // namespace nome::viewer
