#include "viewer/window.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/gl.hpp"

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/io/stl.hpp"
#include "nome/query/pick.hpp"
#include "render/image.hpp"
#include "render/mesh_display_data.hpp"

namespace nome::viewer {
namespace {

constexpr double default_azimuth = 30.0;
constexpr double default_elevation = 25.0;
constexpr double pick_pixels = 8.0;

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// A selected border as the zipper reads it: whole loops from their first vertex, segments end to end
// in the direction they were picked.
BorderSelection zipper_border(const BorderLookup& borders, const Selection::Border& border) {
  BorderSelection out;
  out.start = border.vertices.front();
  out.end = border.is_loop ? out.start : border.vertices.back();
  if (!border.is_loop && border.vertices.size() > 1) {
    const auto loop = borders.loop_vertices(borders.loop_of(out.start));
    const auto at = std::find(loop.begin(), loop.end(), out.start) - loop.begin();
    out.backwards = loop[(at + 1) % loop.size()] != border.vertices[1];
  }
  return out;
}

}  // namespace

Window::Window(GLFWwindow* window, const ViewerOptions& options)
    : window_(window),
      options_(options),
      renderer_(std::make_unique<render::Renderer>()),
      cubes_(std::make_unique<render::CubeSet>()),
      border_lines_(std::make_unique<render::LineSet>()),
      rim_lines_(std::make_unique<render::LineSet>()),
      recent_(RecentFiles::default_store()),
      autosave_(Autosave::default_folder()) {
  register_keys();
  camera_.set_view(default_azimuth, default_elevation);
  log_.set_echo(options.script.has_value());
  if (options.script) {
    try {
      script_ = read_script(*options.script);
    } catch (const Error& e) {
      log_.error(e.what());
      exit_status_ = 1;
      should_close_ = true;
    }
  }
  if (options.file) open(*options.file);
  if (options.file && !session_) exit_status_ = 1;
  for (const std::filesystem::path& anom : options.anom_files) apply_anom(anom);
  log_.info("Press ? or F1 for the keys; left drag turns, right drag pans, the wheel zooms.");
}

Window::~Window() = default;

void Window::register_keys() {
  keys_.add(GLFW_KEY_SLASH, KeyModifier::shift, "show or hide this help",
            [this] { show_help_ = !show_help_; });
  keys_.add(GLFW_KEY_F1, 0, "show or hide this help", [this] { show_help_ = !show_help_; });
  keys_.add(GLFW_KEY_O, KeyModifier::control, "open a file", [this] {
    browser_purpose_ = BrowserPurpose::open;
    browser_.open("Open", session_ ? session_->path().parent_path() : std::filesystem::path{},
                  {".nome", ".anom", ".sif", ".slf", ".obj", ".stl"}, "Open");
  });
  for (int i = 0; i < 4; ++i)
    keys_.add(GLFW_KEY_1 + i, KeyModifier::control, "open recent file " + std::to_string(i + 1), [this, i] {
      if (std::size_t(i) < recent_.files().size()) request_open(recent_.files()[i]);
    });
  keys_.add(GLFW_KEY_S, KeyModifier::control, "save the scene (.nome)", [this] { save(std::nullopt); });
  keys_.add(GLFW_KEY_S, KeyModifier::control | KeyModifier::shift, "save the scene as (.nome)", [this] {
    if (!session_ || !session_->scene()) return;
    browser_purpose_ = BrowserPurpose::save;
    browser_.open("Save As", session_->path().parent_path(), {".nome"}, "Save",
                  session_->path().filename().string());
  });
  keys_.add(GLFW_KEY_E, KeyModifier::control, "export the stage on screen (.stl, .obj)", [this] {
    if (!session_) return;
    browser_purpose_ = BrowserPurpose::export_mesh;
    browser_.open("Export", session_->path().parent_path(), {".stl", ".obj"}, "Save",
                  session_->path().stem().string() + ".stl");
  });
  keys_.add(GLFW_KEY_Q, KeyModifier::control, "quit", [this] { request_quit(); });
  keys_.add(GLFW_KEY_I, 0, "zoom in", [this] { camera_.zoom(1.0 / 1.25); });
  keys_.add(GLFW_KEY_O, 0, "zoom out", [this] { camera_.zoom(1.25); });
  keys_.add(GLFW_KEY_W, 0, "wire mode / polygon mode", [this] {
    display_.show_faces = !display_.show_faces;
    display_.show_wireframe = !display_.show_faces || display_.show_wireframe;
  });
  keys_.add(GLFW_KEY_S, 0, "smooth / flat shading", [this] {
    display_.shading =
        display_.shading == render::Shading::smooth ? render::Shading::flat : render::Shading::smooth;
  });
  keys_.add(GLFW_KEY_X, 0, "back-face culling on / off", [this] {
    display_.back_faces = display_.back_faces == render::BackFacePolicy::cull
                              ? render::BackFacePolicy::different
                              : render::BackFacePolicy::cull;
  });
  keys_.add(GLFW_KEY_F, 0, "frame everything", [this] { frame_all(); });
  keys_.add(GLFW_KEY_H, KeyModifier::control, "reset the view", [this] { reset_view(); });
  keys_.add(GLFW_KEY_KP_1, 0, "view from the front", [this] { set_view(0.0, 0.0); });
  keys_.add(GLFW_KEY_KP_3, 0, "view from the right", [this] { set_view(90.0, 0.0); });
  keys_.add(GLFW_KEY_KP_7, 0, "view from the top", [this] { set_view(0.0, 90.0); });
  keys_.add(GLFW_KEY_P, 0, "save a screenshot PNG", [this] { pending_screenshot_ = next_screenshot_path(); });
  keys_.add(GLFW_KEY_L, 0, "show or hide the log panel", [this] { show_log_ = !show_log_; });
  keys_.add(GLFW_KEY_Z, KeyModifier::control, "undo", [this] { run_action("undo"); });
  keys_.add(GLFW_KEY_Y, KeyModifier::control, "redo", [this] { run_action("redo"); });
  keys_.add(GLFW_KEY_ENTER, 0, "add a polygon through the selected vertices",
            [this] { run_action("add-polygon"); });
  keys_.add(GLFW_KEY_A, KeyModifier::control, "accept the temporary faces (consolidate)",
            [this] { run_action("accept"); });
  keys_.add(GLFW_KEY_DELETE, 0, "delete the selected faces", [this] { run_action("delete"); });
  keys_.add(GLFW_KEY_ESCAPE, 0, "clear the selection", [this] {
    selection_.clear();
    refresh_selection();
  });
}

// ---------------------------------------------------------------------------------------------- files

bool Window::drop(const std::vector<std::filesystem::path>& paths) {
  // One document per window: the last scene or mesh dropped opens, then the .anom files apply to it.
  std::vector<std::filesystem::path> files, anoms;
  for (const std::filesystem::path& path : paths) (is_anom_file(path) ? anoms : files).push_back(path);
  if (files.size() > 1) log_.info("several files dropped: opening the last, " + files.back().string());
  bool done = true;
  if (!files.empty()) {
    request_open(files.back());
    done = unsaved_prompt_ || (session_ && session_->path() == files.back());
  }
  for (const std::filesystem::path& anom : anoms) done = apply_anom(anom) && done;
  return done;
}

void Window::request_open(const std::filesystem::path& path) {
  if (is_anom_file(path)) {
    apply_anom(path);
    return;
  }
  if (!session_ || !session_->is_modified()) {
    open(path);
    return;
  }
  unsaved_prompt_ = UnsavedPrompt{path};
  log_.info("open " + path.filename().string() + ": " + session_->path().filename().string() +
            " has unsaved changes (save first, open without saving, or cancel)");
}

void Window::open(const std::filesystem::path& path) {
  try {
    Session session = Session::open(path);
    session_.emplace(std::move(session));
    recovery_offer_ = autosave_.pending_recovery(path);
    std::error_code ec;
    file_time_ = std::filesystem::last_write_time(path, ec);
    recent_.add(path);
    selection_.clear();
    shown_.reset();
    picking_bvh_.reset();
    has_request_ = false;
    update_stage();
    // The first picture of a file waits for its geometry, so that it can be framed.
    while (job_.is_busy() && !shown_) update_stage();
    reset_view();
    const PolygonSoup& soup = session_->scene_soup();
    log_.info("opened " + path.string() + " (" + std::to_string(soup.num_vertices()) + " vertices, " +
              std::to_string(soup.num_faces()) + " faces)");
    glfwSetWindowTitle(window_, ("Nome - " + path.filename().string()).c_str());
  } catch (const std::exception& e) {
    log_.error(e.what());
  }
}

bool Window::apply_anom(const std::filesystem::path& path) {
  if (!session_) {
    log_.error(path.string() + ": an .anom file applies to an open scene: open its .nome first");
    return false;
  }
  try {
    session_->apply_anom(path);
    recent_.add(path);
    selection_.clear();
    update_stage();
    log_.info("applied " + path.string() + " to " + session_->path().filename().string() + " (" +
              std::to_string(session_->scene_soup().num_faces()) + " faces)");
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

void Window::save(const std::optional<std::filesystem::path>& path) {
  if (!session_ || !session_->scene()) {
    log_.error("save: only scene files (.nome) are saved; File > Export writes .stl and .obj");
    return;
  }
  const std::filesystem::path target = path ? *path : session_->path();
  try {
    save_session(target);
    std::error_code ec;
    file_time_ = std::filesystem::last_write_time(target, ec);
    recent_.add(target);
    log_.info("saved " + target.string());
  } catch (const std::exception& e) {
    log_.error(e.what());
  }
}

void Window::save_session(const std::filesystem::path& target) {
  const std::filesystem::path previous = session_->path();
  const std::vector<std::string> left_out = session_->save(target);
  if (previous != target) autosave_.discard(previous);  // its changes went to the new file
  if (!left_out.empty()) {
    std::string names;
    for (const std::string& name : left_out) names += (names.empty() ? "" : ", ") + name;
    log_.warning("not saved, kept in this session: " + std::to_string(left_out.size()) +
                 " edits whose vertices or faces are gone at the current slider values (" + names + ")");
  }
}

void Window::set_slider(Index parameter, double value) {
  try {
    session_->set_parameter(parameter, value);
  } catch (const std::exception& e) {
    log_.error(e.what());
  }
}

void Window::poll_file_changes() {
  if (!session_) return;
  const double now = glfwGetTime();
  if (now - last_file_check_ < 0.5) return;
  last_file_check_ = now;
  std::error_code ec;
  const auto time = std::filesystem::last_write_time(session_->path(), ec);
  if (ec || time == file_time_) return;
  file_time_ = time;
  try {
    session_->reload();
    log_.info("reloaded " + session_->path().filename().string());
  } catch (const std::exception& e) {
    // The last good geometry stays on screen.
    log_.error(e.what());
  }
}

void Window::export_mesh(const std::filesystem::path& path) {
  if (!shown_mesh()) throw InvalidInputError("export: nothing is shown");
  const std::string ext = lower_extension(path);
  if (ext == ".obj")
    write_obj(path, *shown_mesh());
  else if (ext == ".stl")
    write_stl(path, *shown_mesh());
  else
    throw InvalidInputError("export: the file must end in .stl or .obj, found '" + path.string() + "'");
  log_.info("exported " + path.string());
}

std::filesystem::path Window::next_screenshot_path() const {
  const std::filesystem::path folder = std::filesystem::current_path();
  for (int i = 1;; ++i) {
    const auto candidate = folder / ("nome-screenshot-" + std::to_string(i) + ".png");
    if (!std::filesystem::exists(candidate)) return candidate;
  }
}

void Window::save_screenshot(const std::filesystem::path& path) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render::Image image(width, height);
  std::vector<std::uint8_t> rows(image.rgba.size());
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  // GL reads bottom row first; PNG stores the top row first.
  const std::size_t stride = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(rows.data() + std::size_t(height - 1 - y) * stride, stride, image.rgba.data() + y * stride);
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  render::write_png(path, image);
  log_.info("screenshot " + path.string());
}

// --------------------------------------------------------------------------------------------- camera

glm::dvec2 Window::window_size() const {
  int width = 0, height = 0;
  glfwGetWindowSize(window_, &width, &height);
  return {std::max(width, 1), std::max(height, 1)};
}

double Window::aspect() const {
  const glm::dvec2 size = window_size();
  return size.x / size.y;
}

ScreenProjection Window::projection() const {
  return camera_.screen_projection(window_size());
}

void Window::frame_all() {
  if (!shown_mesh()) return;
  if (rim_points_.empty()) {
    camera_.fit(shown_mesh()->positions(), aspect());
    return;
  }
  std::vector<Vec3> points(shown_mesh()->positions().begin(), shown_mesh()->positions().end());
  points.insert(points.end(), rim_points_.begin(), rim_points_.end());
  camera_.fit(points, aspect());
}

void Window::reset_view() {
  set_view(default_azimuth, default_elevation);
}

void Window::set_view(double azimuth, double elevation) {
  camera_.set_view(azimuth, elevation);
  frame_all();
}

// ------------------------------------------------------------------------------------ geometry, picks

void Window::update_stage() {
  if (!session_) return;
  if (!has_request_ || session_->version() != requested_version_ || settings_ != requested_settings_) {
    // A newer request supersedes the one in flight; the scene's polygons are copied for the job.
    if (session_->version() != requested_version_ || !has_request_) refresh_rim_lines();
    requested_version_ = session_->version();
    requested_settings_ = settings_;
    has_request_ = true;
    job_.submit([this, input = session_->pipeline_input(), parts = session_->face_parts(),
                 settings = settings_](std::stop_token stop) {
      auto result = pipeline_.run(input, settings, stop);
      if (result) result->parts = parts;
      return result;
    });
  }
  // Short work shows in the frame that asked for it; longer work leaves the last picture up meanwhile.
  try {
    if (auto result = job_.take(std::chrono::milliseconds(30)); result && *result)
      show_result(std::move(**result));
  } catch (const std::exception& e) {
    // The last good geometry stays on screen.
    log_.error(e.what());
  }
  try {
    take_picking_bvh(std::chrono::milliseconds(0));
    prefetch_picking_bvh();
  } catch (const std::exception& e) {
    // The next pick builds it on the UI thread instead.
    log_.warning("picking structure: " + std::string(e.what()));
  }
}

void Window::show_result(StageResult result) {
  const Mesh* old = shown_mesh();
  const Mesh& mesh = *result.mesh;
  const bool is_same_topology = old && old->num_vertices() == mesh.num_vertices() &&
                                old->face_offsets() == mesh.face_offsets() &&
                                old->corner_vertices() == mesh.corner_vertices();
  if (!is_same_topology && !selection_.is_empty()) {
    selection_.clear();
    log_.info("selection cleared: the displayed mesh changed its connectivity");
  }
  for (const std::string& w : result.warnings) log_.warning(w);
  for (const std::string& note : result.notes) log_.info(note);
  buffers_ = std::make_unique<render::MeshBuffers>(result.display);
  picking_bvh_.reset();
  shown_time_ = glfwGetTime();
  shown_ = std::move(result);
  apply_face_colors();
  refresh_selection();
}

const TriangleBvh& Window::picking_bvh() {
  if (!picking_bvh_ && bvh_job_.is_busy()) take_picking_bvh(std::chrono::minutes(1));
  if (!picking_bvh_) picking_bvh_ = std::make_shared<const TriangleBvh>(*shown_mesh());
  return *picking_bvh_;
}

void Window::prefetch_picking_bvh() {
  constexpr double rest_seconds = 0.25;
  if (!shown_ || picking_bvh_ || job_.is_busy() || bvh_job_.is_busy() ||
      glfwGetTime() - shown_time_ < rest_seconds)
    return;
  bvh_job_.submit([mesh = shown_->mesh](std::stop_token) {
    return PickingBvh{mesh, std::make_shared<const TriangleBvh>(*mesh)};
  });
}

void Window::take_picking_bvh(std::chrono::milliseconds patience) {
  // A BVH of a mesh no longer shown is dropped.
  if (auto done = bvh_job_.take(patience); done && shown_ && done->mesh == shown_->mesh)
    picking_bvh_ = done->bvh;
}

void Window::apply_face_colors() {
  if (!shown_ || !buffers_) return;
  // Faces keep their order through the scene and merged stages: the edited ones take their colours.
  auto colors = shown_->display.face_colors;
  const FaceParts& parts = shown_->parts;
  if (is_editable(shown_->stage) &&
      colors.size() == std::size_t(parts.scene) + parts.consolidated + parts.temporary) {
    auto paint = [&](Index first, Index count, glm::vec3 c) {
      for (Index f = first; f < first + count; ++f)
        colors[f] = {std::uint8_t(c.r * 255.0f + 0.5f), std::uint8_t(c.g * 255.0f + 0.5f),
                     std::uint8_t(c.b * 255.0f + 0.5f), 255};
    };
    paint(parts.scene, parts.consolidated, consolidated_color_);
    paint(parts.scene + parts.consolidated, parts.temporary, temporary_color_);
  }
  buffers_->set_face_colors(colors);
}

bool Window::can_edit() const {
  return session_ && shown_ && is_editable(settings_.stage);
}

void Window::set_subdivision(double levels) {
  if (!(levels >= 0 && levels <= 6 && levels == std::floor(levels)))
    throw InvalidInputError("subdiv: expected a level from 0 to 6, found " + std::to_string(levels));
  settings_.subdivision_levels = int(levels);
  // The offset stages subdivide before offsetting: they stay; otherwise the subdivision is shown.
  if (is_editable(settings_.stage)) settings_.stage = Stage::subdivided;
}

void Window::set_offset(double distance) {
  if (!(distance >= 0 && std::isfinite(distance)))
    throw InvalidInputError("offset: expected a distance of 0 or more, found " + std::to_string(distance));
  if (distance == 0) {
    settings_.stage = Stage::subdivided;
    return;
  }
  settings_.offset_distance = distance;
  if (settings_.stage != Stage::subdivided_offset) settings_.stage = Stage::offset;
}

bool Window::run_action(const std::string& action) {
  if (action == "merge") {
    settings_.stage = Stage::merged;
    return true;
  }
  if (!session_) {
    log_.error(action + ": no file is open");
    return false;
  }
  EditOutcome outcome{false, {}};
  if (action == "undo") {
    outcome = {session_->undo(), "nothing to undo"};
    if (outcome.applied) outcome.message = "undone";
  } else if (action == "redo") {
    outcome = {session_->redo(), "nothing to redo"};
    if (outcome.applied) outcome.message = "redone";
  } else if (action == "accept") {
    outcome = session_->accept_temporary();
  } else if (action == "clear") {
    outcome = session_->clear_temporary();
  } else if (!can_edit()) {
    log_.error(action + ": the " + to_string(settings_.stage) +
               " stage is computed from the scene; switch to the scene or merged stage to edit");
    return false;
  } else if (action == "add-polygon") {
    outcome = session_->add_polygon(*shown_mesh(), selection_.vertices());
  } else if (action == "delete") {
    outcome = session_->delete_faces(*shown_mesh(), selection_.faces());
  } else if (action == "zip") {
    const auto& borders = selection_.borders();
    if (borders.size() != 2) {
      log_.error("zip: select two borders first (border modes), found " + std::to_string(borders.size()));
      return false;
    }
    outcome = session_->zipper(*shown_mesh(), zipper_border(*shown_->borders, borders[0]),
                               zipper_border(*shown_->borders, borders[1]), zipper_options_);
  } else {
    log_.error("unknown action '" + action + "'");
    return false;
  }
  if (!outcome.applied) {
    log_.error(action + ": " + outcome.message);
    return false;
  }
  log_.info(action + ": " + (outcome.message.empty() ? std::string("done") : outcome.message));
  // The picked elements went into the edit (or went away with it).
  if (action == "add-polygon" || action == "delete" || action == "zip") {
    selection_.clear();
    refresh_selection();
  }
  return true;
}

void Window::refresh_selection() {
  if (!shown_mesh() || !buffers_) return;
  const Mesh& mesh = *shown_mesh();
  buffers_->set_selected_faces(selection_.faces());
  std::vector<Index> marked(selection_.vertices().begin(), selection_.vertices().end());
  // The first vertex of each whole border is the zipper's matching point: marked as a cube.
  for (const auto& border : selection_.borders())
    if (border.is_loop && !border.vertices.empty()) marked.push_back(border.vertices[0]);
  std::vector<render::CubeMarker> markers = render::vertex_markers(mesh, marked, display_.selection_color);
  for (const render::CubeMarker& m :
       render::vertex_markers(mesh, selection_.pending_ends(), {0.1f, 0.7f, 0.3f}))
    markers.push_back(m);
  cubes_->set(markers);
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> segments;
  for (const auto& border : selection_.borders()) {
    const std::uint32_t first = std::uint32_t(points.size());
    for (Index v : border.vertices) points.push_back(glm::vec3(mesh.position(v)));
    const std::uint32_t n = std::uint32_t(border.vertices.size());
    for (std::uint32_t i = 0; i + 1 < n; ++i) segments.insert(segments.end(), {first + i, first + i + 1});
    if (border.is_loop && n > 2) segments.insert(segments.end(), {first + n - 1, first});
  }
  border_lines_->set(points, segments);
}

void Window::refresh_rim_lines() {
  rim_points_.clear();
  std::vector<std::uint32_t> segments;
  if (const scene::Scene* scene = session_->scene())
    for (const scene::SceneInstance& instance : scene->instances())
      for (const scene::RimLine& rim : instance.geometry.rims) {
        const auto first = std::uint32_t(rim_points_.size());
        const auto n = std::uint32_t(rim.vertices.size());
        for (Index v : rim.vertices) rim_points_.push_back(instance.geometry.soup.positions[v]);
        for (std::uint32_t i = 0; i + 1 < n; ++i) segments.insert(segments.end(), {first + i, first + i + 1});
        if (rim.is_loop && n > 2) segments.insert(segments.end(), {first + n - 1, first});
      }
  const std::vector<glm::vec3> points(rim_points_.begin(), rim_points_.end());
  rim_lines_->set(points, segments);
}

void Window::click(glm::dvec2 pixel) {
  if (!shown_mesh()) return;
  const Mesh& mesh = *shown_mesh();
  const TriangleBvh& bvh = picking_bvh();
  const ScreenProjection p = projection();
  std::string hint;
  auto is_in = [](const std::vector<Index>& items, Index i) {
    return std::find(items.begin(), items.end(), i) != items.end();
  };
  switch (selection_.mode()) {
    case SelectionMode::face:
      if (const auto face = pick_face(bvh, p, pixel)) {
        selection_.click_face(*face);
        hint = "face " + mesh.face_label(*face) +
               (is_in(selection_.faces(), *face) ? " selected" : " deselected");
      }
      break;
    case SelectionMode::vertex:
      if (const auto v = pick_vertex(mesh, bvh, p, pixel, pick_pixels)) {
        selection_.click_vertex(*v);
        hint = "vertex " + mesh.vertex_label(*v) +
               (is_in(selection_.vertices(), *v) ? " selected" : " deselected");
      }
      break;
    case SelectionMode::border:
    case SelectionMode::border_partial:
      if (const auto v = pick_vertex(mesh, bvh, p, pixel, pick_pixels)) {
        const std::size_t before = selection_.borders().size();
        hint = selection_.click_border_vertex(*shown_->borders, *v);
        if (hint.empty() && selection_.borders().size() > before) {
          const auto& border = selection_.borders().back();
          hint = std::string(border.is_loop ? "border" : "partial border") + " of " +
                 std::to_string(border.vertices.size()) + " vertices selected, from " +
                 mesh.vertex_label(border.vertices.front());
        }
      }
      break;
  }
  if (!hint.empty() && !is_editable(settings_.stage))
    hint += std::string(" in the ") + to_string(settings_.stage) +
            " stage (to look; edits need the scene or merged stage)";
  if (!hint.empty()) log_.info(hint);
  refresh_selection();
}

bool Window::double_click(glm::dvec2 pixel) {
  // The orbit centre moves to the picked point; the eye stays where it is.
  if (!shown_) return false;
  const auto hit = picking_bvh().cast_nearest(ray_through_pixel(projection(), pixel));
  if (!hit) {
    log_.info("double-click: no surface under the cursor, the orbit centre stays");
    return false;
  }
  char where[96];
  std::snprintf(where, sizeof where, "orbit centre at (%.6g, %.6g, %.6g)", hit->point.x, hit->point.y,
                hit->point.z);
  log_.info(where);
  const glm::dvec3 eye = camera_.eye();
  camera_.target = hit->point;
  camera_.distance = std::max(glm::length(eye - hit->point), 1e-9);
  const glm::dvec3 back = glm::normalize(eye - hit->point);
  // Keep the up direction as close as possible to the current one while looking at the new centre.
  const glm::dvec3 up_now = camera_.orientation * glm::dvec3(0.0, 1.0, 0.0);
  glm::dvec3 right = glm::cross(up_now, back);
  if (glm::dot(right, right) < 1e-18) return true;
  right = glm::normalize(right);
  camera_.orientation = glm::normalize(glm::quat_cast(glm::dmat3(right, glm::cross(back, right), back)));
  return true;
}

// ---------------------------------------------------------------------------------------------- input

void Window::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  const glm::dvec2 position(x, y);
  const glm::dvec2 size = window_size();
  auto to_ndc = [&](glm::dvec2 p) { return glm::dvec2(2.0 * p.x / size.x - 1.0, 1.0 - 2.0 * p.y / size.y); };

  if (pressed_button_ < 0 && !io.WantCaptureMouse) {
    for (int button = 0; button < 3; ++button) {
      if (!ImGui::IsMouseClicked(button)) continue;
      pressed_button_ = button;
      press_position_ = last_position_ = position;
      is_dragging_ = false;
      if (button == 0 && ImGui::IsMouseDoubleClicked(0)) double_click(position);
      break;
    }
    if (io.MouseWheel != 0.0f) camera_.zoom(std::pow(0.88, double(io.MouseWheel)));
  }
  if (pressed_button_ < 0) return;
  if (glm::length(position - press_position_) >= click_pixels) is_dragging_ = true;
  if (is_dragging_ && position != last_position_) {
    if (pressed_button_ == 0)
      camera_.arcball(to_ndc(last_position_), to_ndc(position), aspect());
    else
      camera_.pan(to_ndc(last_position_), to_ndc(position), aspect());
  }
  last_position_ = position;
  if (ImGui::IsMouseDown(pressed_button_)) return;
  if (!is_dragging_) {
    if (pressed_button_ == 0) click(press_position_);
    if (pressed_button_ == 1) {
      selection_.clear();
      refresh_selection();
    }
  }
  pressed_button_ = -1;
}

void Window::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  const int modifiers = (io.KeyShift ? KeyModifier::shift : 0) | (io.KeyCtrl ? KeyModifier::control : 0);
  for (const KeyBinding& binding : keys_.bindings()) {
    if (binding.modifiers != modifiers || !ImGui::IsKeyPressed(binding.key, false)) continue;
    binding.action();
    break;
  }
}

// --------------------------------------------------------------------------------------------- script

void Window::run_script_step() {
  // The first frames lay out the panels; a screenshot taken then would show them half-built.
  // Each command sees the result of the one before: the stage being computed is awaited.
  if (script_next_ >= script_.size() || frames_drawn_ < 3 || pending_screenshot_ || job_.is_busy()) return;
  const ScriptCommand& command = script_[script_next_++];
  try {
    if (!run_command(command)) {
      exit_status_ = 1;
      log_.error(options_.script->string() + ":" + std::to_string(command.line) + ": the command failed");
    }
  } catch (const std::exception& e) {
    exit_status_ = 1;
    log_.error(options_.script->string() + ":" + std::to_string(command.line) + ": " + e.what());
  }
}

bool Window::run_command(const ScriptCommand& c) {
  using Kind = ScriptCommand::Kind;
  switch (c.kind) {
    case Kind::mode:
      if (c.words[0] == "vertex") selection_.set_mode(SelectionMode::vertex);
      if (c.words[0] == "face") selection_.set_mode(SelectionMode::face);
      if (c.words[0] == "border") selection_.set_mode(SelectionMode::border);
      if (c.words[0] == "border-partial") selection_.set_mode(SelectionMode::border_partial);
      return true;
    case Kind::click:
      click({c.numbers[0], c.numbers[1]});
      return true;
    case Kind::double_click:
      return double_click({c.numbers[0], c.numbers[1]});
    case Kind::drop:
      return drop({c.words[0]});
    case Kind::prompt:
      if (!unsaved_prompt_) throw InvalidInputError("prompt: no question about unsaved changes is open");
      answer_unsaved_prompt(c.words[0] == "save"      ? UnsavedAnswer::save
                            : c.words[0] == "discard" ? UnsavedAnswer::discard
                                                      : UnsavedAnswer::cancel);
      return true;
    case Kind::key:
      if (keys_.press(c.words[0])) return true;
      throw InvalidInputError("no key '" + c.words[0] + "' (press ? in the viewer for the list)");
    case Kind::view:
      set_view(c.numbers[0], c.numbers[1]);
      return true;
    case Kind::screenshot:
      pending_screenshot_ = c.words[0];
      return true;
    case Kind::export_file:
      export_mesh(c.words[0]);
      return true;
    case Kind::recover:
      if (!recovery_offer_) throw InvalidInputError("recover: no unsaved changes are offered for restoring");
      answer_recovery(c.words[0] == "restore");
      return true;
    case Kind::quit:
      should_close_ = true;
      return true;
    case Kind::action:
      return run_action(c.words[0]);
    case Kind::set:
      if (!session_) throw InvalidInputError("set: no file is open");
      session_->set_parameter(c.words[0], c.numbers[0]);
      return true;
    case Kind::save:
      if (!session_ || !session_->scene())
        throw InvalidInputError("save: only scene files (.nome) are saved");
      save_session(c.words[0]);
      log_.info("saved " + c.words[0]);
      return true;
    case Kind::subdiv:
      set_subdivision(c.numbers[0]);
      return true;
    case Kind::offset:
      set_offset(c.numbers[0]);
      return true;
  }
  return false;
}

// --------------------------------------------------------------------------------------------- frame

bool Window::frame() {
  poll_file_changes();
  handle_mouse();
  handle_keys();
  update_stage();
  run_script_step();
  draw_scene();
  draw_panels();
  draw_recovery_prompt();
  update_autosave();
  ImGui::Render();
  ++frames_drawn_;
  // A clean end takes the recovery file along, unless it is still on offer.
  if (should_close_ && session_ && !recovery_offer_) autosave_.discard(session_->path());
  return !should_close_;
}

bool Window::is_animating() const {
  return job_.is_busy() || script_next_ < script_.size() || pending_screenshot_ || pressed_button_ >= 0 ||
         frames_drawn_ < 3;
}

void Window::after_draw() {
  if (!pending_screenshot_) return;
  try {
    save_screenshot(*pending_screenshot_);
  } catch (const std::exception& e) {
    log_.error(e.what());
    if (!script_.empty()) exit_status_ = 1;
  }
  pending_screenshot_.reset();
}

void Window::request_quit() {
  if (session_ && session_->is_modified()) {
    unsaved_prompt_ = UnsavedPrompt{};
    log_.info("quit: the scene has unsaved changes (save and quit, quit without saving, or cancel)");
  } else {
    should_close_ = true;
  }
}

void Window::answer_unsaved_prompt(UnsavedAnswer answer) {
  if (!unsaved_prompt_) return;
  const UnsavedPrompt prompt = *unsaved_prompt_;
  unsaved_prompt_.reset();
  if (answer == UnsavedAnswer::cancel) return;
  if (answer == UnsavedAnswer::save) {
    save(std::nullopt);
    // A failed save (logged) leaves the changes where they were: nothing is lost.
    if (session_->is_modified()) return;
  } else if (prompt.open) {
    // The user gave the changes up: no recovery file should offer them back.
    autosave_.discard(session_->path());
  }
  if (prompt.open)
    open(*prompt.open);
  else
    should_close_ = true;
}

void Window::draw_scene() {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  const render::Renderer::Frame frame =
      render::Renderer::Frame::of(camera_, {0, 0}, {std::max(width, 1), std::max(height, 1)});
  renderer_->begin(frame, display_.background);
  if (!buffers_) return;
  renderer_->draw_mesh(*buffers_, frame, display_);
  renderer_->draw_cubes(*cubes_, frame);
  renderer_->draw_lines(*rim_lines_, frame, glm::vec4(rim_color_, 1.0f), display_.highlight_width);
  renderer_->draw_lines(*border_lines_, frame, glm::vec4(display_.selection_color, 1.0f),
                        display_.highlight_width * 1.5f);
}

}  // namespace nome::viewer
