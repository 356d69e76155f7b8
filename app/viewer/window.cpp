#include "viewer/window.hpp"

#include <algorithm>

#include <imgui.h>

#include "nome/error.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/scene/scene_rim_lines.hpp"
#include "render/bounding_box.hpp"
#include "render/image.hpp"
#include "render/rim_segments.hpp"
#include "render/scene_camera.hpp"
#include "viewer/tools/tool_list.hpp"

namespace nome::viewer {

Window::Window(Platform& platform, render::SceneRenderer& renderer, const ViewerOptions& options,
               const ViewerStores& stores)
    : platform_(platform),
      renderer_(renderer),
      sessions_(log_, stores),
      tool_context_{log_,
                    sessions_,
                    stage_,
                    selection_,
                    view_,
                    actions_,
                    display_,
                    layout_settings_,
                    layout_,
                    rims_,
                    platform_,
                    shown_low_,
                    shown_high_,
                    [this] { refresh_selection(); },
                    [this] { paint_faces(); },
                    [this] { update_stage(); }} {
  bind_actions();
  for (std::unique_ptr<Tool>& tool : make_tools()) add_tool(std::move(tool));
  log_.set_echo(options.script.has_value());
  // A scripted session starts from the default layout, so that its pictures and pixels repeat.
  if (!options.script && !stores.layout_file.empty()) {
    layout_file_ = stores.layout_file;
    layout_settings_ = read_layout(layout_file_);
  }
  if (options.script) {
    try {
      script_ = ScriptRunner(*options.script, read_script(*options.script));
    } catch (const Error& e) {
      log_.error(e.what());
      exit_status_ = 1;
      should_close_ = options.quits_on_bad_script;
    }
  }
  sessions_.set_sif_pairing(options.pair_sif_triangles);
  if (options.file) open(*options.file);
  if (options.file && !sessions_.has_session()) exit_status_ = 1;
  for (const std::filesystem::path& anom : options.anom_files) drop({anom});
  log_.info("Press ? or F1 for the keys; left drag turns, right drag pans, the wheel zooms.");
}

Window::~Window() {
  keep_layout();
}

void Window::keep_layout() {
  if (layout_file_.empty()) return;
  layout_settings_.window_size = glm::ivec2(platform_.window_size());
  try {
    write_layout(layout_file_, layout_settings_);
  } catch (const std::exception&) {
    // A layout that cannot be kept only costs the next run its arrangement.
  }
}

// ---------------------------------------------------------------------------------------------- frame

bool Window::frame(const InputFrame& input) {
  apply_style();
  // Laid out before the mouse is read (the press lands where the last frame showed the viewport) and
  // again after the script, whose keys and commands may change it.
  arrange_layout();
  sessions_.update(platform_.now());
  last_cursor_ = input.cursor;
  const bool is_taken = std::any_of(tools_.begin(), tools_.end(),
                                    [&](const auto& tool) { return tool->take_input(tool_context_, input); });
  if (!is_taken) {
    handle_mouse(input);
    for (const KeyPress& key : input.keys)
      if (actions_.press(key.key, key.modifiers)) break;
  }
  update_stage();
  // The first frames lay out the panels; a screenshot taken then would show them half-built. Each
  // command sees the result of the one before: the stage and busy tools' work are awaited.
  if (frames_drawn_ >= 3 && !pending_screenshot_ && !stage_.is_busy() && !is_any_tool_busy() &&
      settle_frames_ == 0)
    script_.step(*this, log_);
  if (script_.has_failed()) exit_status_ = 1;
  arrange_layout();
  for (const std::unique_ptr<Tool>& tool : tools_) tool->before_draw(tool_context_);
  render::DisplaySettings shown_display = display_;
  shown_display.shading =
      render::shown_shading(display_.shading, stage_.shown() && stage_.shown()->is_smoothed);
  shown_display.lights = display_.uses_scene_lights ? scene_lights_ : render::SceneLights{};
  renderer_.draw(view_.camera(), platform_.framebuffer_size(), viewport_pixels(), shown_display);
  draw_panels();
  draw_prompts();
  record_view_state();
  if (is_layout_print_pending_)
    for (const std::string& line : report_.lines()) log_.info(line);
  is_layout_print_pending_ = false;
  ImGui::Render();
  ++frames_drawn_;
  settle_frames_ = std::max(0, settle_frames_ - 1);
  // A clean end takes the recovery file along, unless it is still on offer.
  if (should_close_ && !sessions_.recovery_offer()) sessions_.discard_recovery();
  return !should_close_;
}

bool Window::is_animating() const {
  const bool is_tool_animating =
      std::any_of(tools_.begin(), tools_.end(), [](const auto& t) { return t->is_animating(); });
  return stage_.is_busy() || is_tool_animating || !script_.is_done() || pending_screenshot_ ||
         view_.is_pressed() || frames_drawn_ < 3 || settle_frames_ > 0;
}

void Window::after_draw() {
  if (!pending_screenshot_) return;
  try {
    render::Image image = renderer_.read_pixels(platform_.framebuffer_size());
    if (is_screenshot_of_model_) {
      const render::PixelRect r = viewport_pixels();
      image = render::crop(image, r.origin.x, image.height - r.origin.y - r.size.y, r.size.x, r.size.y);
    }
    render::write_png(*pending_screenshot_, image);
    log_.info("screenshot " + pending_screenshot_->string());
  } catch (const std::exception& e) {
    log_.error(e.what());
    if (script_.has_commands()) exit_status_ = 1;
  }
  pending_screenshot_.reset();
}

void Window::handle_mouse(const InputFrame& input) {
  const auto event = view_.handle(input, layout_.viewport);
  if (!event) return;
  switch (event->kind) {
    case MouseEvent::Kind::click:
      click(event->pixel);
      break;
    case MouseEvent::Kind::double_click:
      double_click(event->pixel);
      break;
    case MouseEvent::Kind::right_click:
      actions_.run(Action::clear_selection);
      break;
  }
}

// ---------------------------------------------------------------------------------------------- files

void Window::run_script(const std::string& text, const std::string& origin) {
  script_.append(origin, parse_script(text, origin));
  log_.set_echo(true);
}

bool Window::drop(const std::vector<std::filesystem::path>& paths) {
  std::vector<std::filesystem::path> files, anoms;
  for (const std::filesystem::path& path : paths) (is_anom_file(path) ? anoms : files).push_back(path);
  if (files.size() > 1) log_.info("several files dropped: opening the last, " + files.back().string());
  bool is_done = true;
  if (!files.empty()) {
    request_open(files.back());
    is_done = prompts_.unsaved() || (sessions_.has_session() && sessions_.path() == files.back());
  }
  for (const std::filesystem::path& anom : anoms) {
    const bool is_applied = sessions_.apply_anom(anom);
    if (is_applied) selection_.clear();
    is_done = is_applied && is_done;
  }
  update_stage();
  return is_done;
}

void Window::request_open(const std::filesystem::path& path) {
  if (is_anom_file(path)) {
    drop({path});
    return;
  }
  if (!sessions_.is_modified() && !has_unsaved_changes()) {
    open(path);
    return;
  }
  prompts_.ask_unsaved({path});
  log_.info("open " + path.filename().string() + ": " + sessions_.path().filename().string() +
            " has unsaved changes (save first, open without saving, or cancel)");
}

void Window::open(const std::filesystem::path& path) {
  if (!sessions_.open(path)) return;
  parameters_ = {};
  selection_.clear();
  stage_.clear();
  apply_file_defaults();
  recorded_ = view_state();  // the file's defaults are where the history starts
  update_stage();
  // The first picture of a file waits for its geometry, so that it can be framed.
  while (stage_.is_busy() && !stage_.shown()) update_stage();
  set_view(ViewController::default_azimuth, ViewController::default_elevation);
  platform_.set_title("Nome - " + path.filename().string());
}

void Window::apply_file_defaults() {
  const render::DisplaySettings plain;
  display_.background = plain.background;
  display_.front_color = plain.front_color;
  display_.back_color = plain.back_color;
  view_.set_lens({});
  const scene::Scene* scene = sessions_.scene();
  if (!scene) return;
  const scene::RenderDefaults colors = scene->render_defaults();
  view_.set_lens(render::scene_lens(colors));
  if (colors.background) display_.background = glm::vec4(*colors.background, 1.0f);
  if (colors.front_color) display_.front_color = *colors.front_color;
  if (colors.back_color) {
    display_.back_faces = render::BackFacePolicy::different;
    display_.back_color = *colors.back_color;
  }
  // A file that asks for subdivision or an offset is shown with them, as JIPCAD shows it.
  const scene::StageSettings stages = scene->stage_settings();
  followed_stages_ = stages;
  followed_values_.clear();
  for (const scene::Parameter& p : scene->parameters()) followed_values_.push_back(p.value);
  PipelineSettings& settings = stage_.settings();
  if (stages.subdivision_levels) {
    settings.subdivision_levels = *stages.subdivision_levels;
    if (!passes_through(settings.stage, Stage::subdivided)) settings.stage = Stage::subdivided;
  }
  if (stages.boundary) settings.boundary = *stages.boundary;
  if (stages.offset_distance) {
    settings.offset_distance = *stages.offset_distance;
    if (!passes_through(settings.stage, Stage::offset)) settings.stage = Stage::offset;
  }
  if (scene::weld_before_subdividing(stages, settings)) log_.info(scene::welding_note);
}

void Window::request_quit() {
  if (!sessions_.is_modified() && !has_unsaved_changes()) {
    should_close_ = true;
    return;
  }
  prompts_.ask_unsaved({});
  log_.info("quit: the scene has unsaved changes (save and quit, quit without saving, or cancel)");
}

void Window::answer_unsaved(UnsavedAnswer answer) {
  if (!prompts_.unsaved()) throw InvalidInputError("prompt: no question about unsaved changes is open");
  const UnsavedQuestion question = prompts_.take_unsaved();
  if (answer == UnsavedAnswer::cancel) return;
  if (answer == UnsavedAnswer::save) {
    // A failed save (logged) leaves the changes where they were: nothing is lost.
    for (const std::unique_ptr<Tool>& tool : tools_)
      if (tool->has_unsaved_changes() && !tool->save_changes(tool_context_)) return;
    if (sessions_.is_modified() && (!sessions_.save_logged(std::nullopt) || sessions_.is_modified())) return;
  } else if (question.open) {
    // The user gave the changes up: no recovery file should offer them back.
    sessions_.discard_recovery();
  }
  if (question.open)
    open(*question.open);
  else
    should_close_ = true;
}

void Window::answer_recovery(bool restore) {
  if (!sessions_.recovery_offer())
    throw InvalidInputError("recover: no unsaved changes are offered for restoring");
  if (!sessions_.answer_recovery(restore)) return;
  selection_.clear();
  stage_.invalidate();
}

// ------------------------------------------------------------------------------------ geometry, picks

void Window::follow_file_stages(const scene::Scene& scene) {
  std::vector<double> values;
  for (const scene::Parameter& p : scene.parameters()) values.push_back(p.value);
  if (values == followed_values_) return;
  followed_values_ = std::move(values);
  scene::StageSettings stages;
  try {
    stages = scene.stage_settings();
  } catch (const Error& e) {
    log_.error(e.what());
    return;
  }
  PipelineSettings& settings = stage_.settings();
  if (stages.subdivision_levels && stages.subdivision_levels != followed_stages_.subdivision_levels)
    settings.subdivision_levels = *stages.subdivision_levels;
  if (stages.offset_distance && stages.offset_distance != followed_stages_.offset_distance)
    settings.offset_distance = *stages.offset_distance;
  followed_stages_ = stages;
}

void Window::update_stage() {
  const Session* session = sessions_.session();
  if (!session) return;
  if (const scene::Scene* scene = session->scene()) follow_file_stages(*scene);
  const InputChange change = stage_.request(*session);
  const scene::Scene* scene = session->scene();
  // A slider that only moved vertices moves the rim lines' vertices; their names, ids and colours stay.
  if (change.geometry == Change::topology || change.face_attributes)
    show_rim_lines(scene ? scene::scene_rim_lines(*scene) : RimLines{});
  else if (change.geometry == Change::positions && scene)
    move_rim_lines(scene::scene_rim_positions(*scene));
  if (change != InputChange{})
    scene_lights_ = scene ? render::scene_lights(scene->render_defaults().lights) : render::SceneLights{};
  try {
    if (auto result = stage_.take_for_frame()) show_result(std::move(*result));
  } catch (const std::exception& e) {
    // The last good geometry stays on screen.
    log_.error(e.what());
  }
  try {
    stage_.prefetch_picking_bvh(platform_.now());
  } catch (const std::exception& e) {
    // The next pick builds it on the UI thread instead.
    log_.warning("picking structure: " + std::string(e.what()));
  }
  for (const std::unique_ptr<Tool>& tool : tools_) tool->update(tool_context_);
}

void Window::show_result(StageResult result) {
  const Mesh* old = stage_.shown_mesh();
  const Mesh& mesh = *result.mesh;
  // Results that share their display topology share their connectivity (the pipeline's change signal).
  const bool is_same_topology = old && stage_.shown()->display.topology == result.display.topology;
  if (!is_same_topology && !selection_.is_empty()) {
    selection_.clear();
    log_.info("selection cleared: the displayed mesh changed its connectivity");
  }
  for (const std::string& w : result.warnings) log_.warning(w);
  for (const std::string& note : result.notes) log_.info(note);
  const render::BoundingBox box = result.display.positions->bounds;
  shown_size_ = box.is_empty() ? glm::dvec3(0.0) : box.max - box.min;
  shown_low_ = box.is_empty() ? glm::dvec3(0.0) : box.min;
  shown_high_ = box.is_empty() ? glm::dvec3(0.0) : box.max;
  renderer_.set_mesh(result.display);
  stage_.show(std::move(result), platform_.now());
  rims_ = pickable_rims(rim_lines_, mesh, stage_.shown()->borders);
  paint_faces();
  refresh_selection();
}

void Window::refresh_selection() {
  if (const Mesh* mesh = stage_.shown_mesh()) {
    std::vector<render::CubeMarker> markers;
    for (const std::unique_ptr<Tool>& tool : tools_)
      for (const render::CubeMarker& marker : tool->markers()) markers.push_back(marker);
    show_selection(renderer_, *mesh, rims_, selection_, display_.selection_color, display_.rim_color,
                   markers);
    show_sharp_edges(renderer_, *mesh);
  }
}

void Window::show_rim_lines(RimLines lines) {
  // Rim vertex ids follow the mesh's: other lines make other ids.
  if (lines.offsets != rim_lines_.offsets && !selection_.is_empty()) {
    selection_.clear();
    log_.info("selection cleared: the rim lines changed");
  }
  rim_lines_ = std::move(lines);
  draw_rim_lines();
}

void Window::move_rim_lines(std::vector<Vec3> positions) {
  if (positions.size() != rim_lines_.positions.size()) {
    show_rim_lines(scene::scene_rim_lines(*sessions_.session()->scene()));
    return;
  }
  rim_lines_.positions = std::move(positions);
  draw_rim_lines();
}

void Window::draw_rim_lines() {
  render::LineSegments drawn;
  render::add_rim_segments(rim_lines_, drawn);
  renderer_.set_lines(render::Overlay::rim, drawn.points, drawn.segments, drawn.colors);
  if (const StageResult* shown = stage_.shown())
    rims_ = pickable_rims(rim_lines_, *shown->mesh, shown->borders);
  refresh_selection();
}

void Window::frame_all() {
  if (!is_layout_known_) {
    is_framing_pending_ = true;
    return;
  }
  if (const Mesh* mesh = stage_.shown_mesh())
    view_.frame(mesh->positions(), rim_lines_.positions, layout_.viewport);
}

void Window::draw_prompts() {
  if (const auto answer = prompts_.draw_unsaved(sessions_.has_scene())) answer_unsaved(*answer);
  const bool is_offered = sessions_.recovery_offer().has_value();
  if (const auto restore = prompts_.draw_recovery(is_offered, sessions_.path())) answer_recovery(*restore);
}

}  // namespace nome::viewer
