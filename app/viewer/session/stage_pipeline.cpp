#include "viewer/session/stage_pipeline.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <thread>

#include "nome/thread_support.hpp"

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

std::optional<StageResult> StagePipeline::run(const SceneInput& input, const PipelineSettings& settings,
                                              nome::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  feed_.feed(pipeline_, input);
  return run_stages(settings, stop);
}

std::optional<StageResult> StagePipeline::run(const PipelineInput& input, const PipelineSettings& settings,
                                              nome::stop_token stop) {
  std::lock_guard lock(mutex_);
  if (stop.stop_requested()) return std::nullopt;
  feed_.forget();
  pipeline_.set_input(input);
  return run_stages(settings, stop);
}

std::optional<StageResult> StagePipeline::run_stages(const PipelineSettings& settings,
                                                     nome::stop_token stop) {
  {
    std::lock_guard progress_lock(progress_mutex_);
    progress_ = {};
  }
  const auto start = std::chrono::steady_clock::now();
  StageResult result;
  result.stage = settings.stage;
  result.is_smoothed = settings.is_smoothing();
  const Mesh& mesh = pipeline_.run(settings);
  result.warnings = pipeline_.warnings();
  // Told once, where the merge is what the user asked to see (not again at each later stage's run).
  if (settings.stage == Stage::merged && pipeline_.work(Stage::merged) != StageWork::cached)
    result.notes.push_back("merged " + std::to_string(pipeline_.merge_summary().glued_edges) +
                           " edge pairs (tolerance " + std::to_string(pipeline_.merge_summary().tolerance) +
                           ")");
  if (stop.stop_requested()) return std::nullopt;
  display(mesh, settings, result);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::shared_ptr<const Mesh> StagePipeline::kept_copy(const Mesh& mesh) {
  for (const std::shared_ptr<Mesh>& copy : copies_)
    if (copy.use_count() == 1) {
      // The last holder elsewhere let go on another thread: its reads come before these writes.
      std::atomic_thread_fence(std::memory_order_acquire);
      // A later stage's positions change places with the copy's older ones (no 24 MB copy per tick at a
      // million faces); the scene's or merge's mesh, which the pipeline keeps as it is, is copied.
      if (!pipeline_.exchange_result_positions(copy->positions())) copy->positions() = mesh.positions();
      copy->face_attributes() = mesh.face_attributes();
      return copy;
    }
  return nullptr;
}

std::shared_ptr<const Mesh> StagePipeline::new_copy(const Mesh& mesh) {
  // Three copies cover the one on screen, the one on its way there and one for a picking structure.
  auto copy = std::make_shared<Mesh>(mesh);
  if (copies_.size() < 3) copies_.push_back(copy);
  return copy;
}

std::shared_ptr<const render::DisplayPositions> StagePipeline::display_positions(
    const Mesh& mesh, const render::DisplayTopology& topology, int threads) {
  auto free =
      std::find_if(positions_.begin(), positions_.end(), [](const auto& p) { return p.use_count() == 1; });
  std::shared_ptr<render::DisplayPositions> out;
  if (free != positions_.end()) {
    std::atomic_thread_fence(std::memory_order_acquire);  // as for the mesh copies
    out = *free;
  } else {
    out = std::make_shared<render::DisplayPositions>();
    if (positions_.size() < 3) positions_.push_back(out);
  }
  // An offset's normals may come with the kernel's result (its surface's): no normal passes here.
  const bool has_normals = pipeline_.display_normals(out->face_normals, out->vertex_normals, threads);
  render::build_display_positions(
      mesh, topology, *out, threads,
      has_normals ? render::DisplayNormals::given : render::DisplayNormals::computed);
  return out;
}

void StagePipeline::display(const Mesh& mesh, const PipelineSettings& settings, StageResult& result) {
  if (last_ && last_->version == pipeline_.result_topology_version()) {
    result.display.topology = last_->display;
    result.borders = last_->borders;
    result.topology = last_->topology;
    result.display.positions = display_positions(mesh, *result.display.topology, settings.threads);
    result.display.face_colors = render::display_face_colors(mesh);
    // A kept copy takes the positions once the display arrays have read them.
    const std::shared_ptr<const Mesh> kept = kept_copy(mesh);
    result.mesh = kept ? kept : new_copy(mesh);
    return;
  }
  // Counted before the mesh is lent (the pipeline's then holds none).
  result.topology = pipeline_.result_report();
  // The pipeline's own result, lent, is what the frame shows: no copy of it before the frame. The copy
  // the pipeline takes back when it needs it (moved vertices) is made afterwards on a thread of its own,
  // beside the frames, or on one thread when the pipeline asks. The scene's or merge's mesh, which the
  // pipeline keeps as it is, is copied beside the display arrays (memory bound).
  copies_.clear();
  auto shown = std::make_shared<Mesh>();
  auto copy_back = std::make_shared<std::future<Mesh>>();
  const bool is_lent = pipeline_.lend_result(
      *shown, [copy_back, shown] { return copy_back->valid() ? copy_back->get() : Mesh(*shown); });
  // Where threads cannot start, the copies are made on this thread, as with one thread.
  const bool is_threaded = settings.threads > 1 && can_start_threads();
  std::future<void> copied;
  if (!is_lent)
    copied = std::async(is_threaded ? std::launch::async : std::launch::deferred, [&] { *shown = mesh; });
  const Mesh& source = is_lent ? *shown : mesh;
  result.display.topology = std::make_shared<const render::DisplayTopology>(
      render::build_display_topology(source, settings.threads));
  result.borders = std::make_shared<const BorderLookup>(source);
  result.display.positions = display_positions(source, *result.display.topology, settings.threads);
  result.display.face_colors = render::display_face_colors(source);
  // One copy in flight at a time, and no run waits for one it does not need: while the last is still
  // being made (new topologies in quick succession), the pipeline copies this result itself if it asks.
  if (is_lent && is_threaded && (!copy_thread_.joinable() || copy_done_->load())) {
    std::packaged_task<Mesh()> copy([shown] { return Mesh(*shown); });
    *copy_back = copy.get_future();
    copy_done_ = std::make_shared<std::atomic<bool>>(false);
    copy_thread_ = nome::jthread([copy = std::move(copy), done = copy_done_]() mutable {
      copy();
      done->store(true);
    });
  } else if (!is_lent) {
    copied.get();
  }
  copies_.push_back(shown);
  result.mesh = shown;
  last_ =
      Shared{result.display.topology, result.borders, result.topology, pipeline_.result_topology_version()};
}

}  // namespace nome::viewer
