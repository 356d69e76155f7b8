#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "nome/error.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/gltf.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/ply.hpp"
#include "nome/io/stl.hpp"
#include "nome/number_text.hpp"
#include "nome/query/pick.hpp"
#include "viewer/window.hpp"

// What each action and script command does in the window: bound once, from the action table's rows.
namespace nome::viewer {
namespace {

std::filesystem::path next_screenshot_path() {
  const std::filesystem::path folder = std::filesystem::current_path();
  for (int i = 1;; ++i) {
    const auto candidate = folder / ("nome-screenshot-" + std::to_string(i) + ".png");
    if (!std::filesystem::exists(candidate)) return candidate;
  }
}

// A handler that always does what it was asked.
template <typename F>
ActionRegistry::Handler always(F f) {
  return [f] {
    f();
    return true;
  };
}

}  // namespace

// Opening and saving files.
void Window::bind_file_actions() {
  for (Action action : {Action::open, Action::save_as, Action::export_mesh})
    actions_.bind(action, always([this, action] { open_browser(action); }));
  const Action recent[] = {Action::open_recent_1, Action::open_recent_2, Action::open_recent_3,
                           Action::open_recent_4};
  for (std::size_t i = 0; i < 4; ++i)
    actions_.bind(recent[i], [this, i] {
      if (i >= sessions_.recent().files().size()) return false;
      request_open(sessions_.recent().files()[i]);
      return true;
    });
  actions_.bind(Action::save, [this] {
    if (!sessions_.save_logged(std::nullopt)) return false;
    platform_.offer_saved_file(sessions_.path());
    return true;
  });
}

// The view: zoom, what is drawn and how, the camera's presets, screenshots.
void Window::bind_view_actions() {
  actions_.bind(Action::zoom_in, always([this] { view_.zoom(1.0 / 1.25); }));
  actions_.bind(Action::zoom_out, always([this] { view_.zoom(1.25); }));
  actions_.bind(Action::toggle_faces, always([this] {
                  display_.draws_faces = !display_.draws_faces;
                  display_.draws_wireframe = !display_.draws_faces || display_.draws_wireframe;
                }));
  actions_.bind(Action::toggle_shading, always([this] {
                  display_.shading = display_.shading == render::Shading::automatic ? render::Shading::smooth
                                     : display_.shading == render::Shading::smooth
                                         ? render::Shading::flat
                                         : render::Shading::automatic;
                }));
  actions_.bind(Action::toggle_culling, always([this] {
                  const bool is_culled = display_.back_faces == render::BackFacePolicy::cull;
                  display_.back_faces =
                      is_culled ? render::BackFacePolicy::different : render::BackFacePolicy::cull;
                }));
  actions_.bind(Action::frame_all, always([this] { frame_all(); }));
  actions_.bind(Action::reset_view, always([this] {
                  set_view(ViewController::default_azimuth, ViewController::default_elevation);
                }));
  actions_.bind(Action::view_front, always([this] { set_view(0.0, 0.0); }));
  actions_.bind(Action::view_right, always([this] { set_view(90.0, 0.0); }));
  actions_.bind(Action::view_top, always([this] { set_view(0.0, 90.0); }));
  actions_.bind(Action::screenshot, always([this] {
                  pending_screenshot_ = next_screenshot_path();
                  is_screenshot_of_model_ = true;
                }));
}

void Window::bind_actions() {
  actions_.bind(Action::toggle_help, always([this] { panels_.is_help_shown = !panels_.is_help_shown; }));
  LayoutSettings& layout = layout_settings_;
  actions_.bind(Action::toggle_log, always([&layout] { layout.is_log_open = !layout.is_log_open; }));
  actions_.bind(Action::toggle_sidebars, always([&layout] {
                  const bool is_any_shown = layout.is_left_shown || layout.is_right_shown;
                  layout.is_left_shown = layout.is_right_shown = !is_any_shown;
                }));
  actions_.bind(Action::toggle_theme, always([&layout] { layout.is_dark = !layout.is_dark; }));
  bind_file_actions();
  actions_.bind(Action::quit, always([this] { request_quit(); }));
  bind_view_actions();
  actions_.bind(Action::clear_selection, always([this] {
                  selection_.clear();
                  refresh_selection();
                }));
  actions_.bind(Action::merge, always([this] { stage_.settings().stage = Stage::merged; }));
  actions_.bind(Action::toggle_sif_pairing, [this] {
    if (!sessions_.set_sif_pairing(!sessions_.is_sif_pairing_on())) return false;
    // A reopened .sif file is a new session: what was shown and picked belongs to the old one.
    if (sif_pairing()) {
      selection_.clear();
      stage_.clear();
    }
    return true;
  });
  actions_.bind(
      Action::toggle_parameter_lock, always([this] {
        sessions_.set_parameter_lock(!sessions_.is_parameter_lock_on());
        log_.info(std::string("generator parameters ") +
                  (sessions_.is_parameter_lock_on() ? "locked while the document has edits" : "free"));
      }));
  for (Action action : {Action::add_polygon, Action::accept, Action::clear_temporary, Action::delete_faces,
                        Action::zip, Action::toggle_sharp, Action::undo, Action::redo})
    actions_.bind(action, [this, action] { return edit(action); });
}

void Window::open_browser(Action action) {
  const std::filesystem::path path = sessions_.path();
  const std::filesystem::path folder = path.parent_path();
  if (action == Action::open) {
    if (platform_.pick_file_to_open()) return;
    browser_.open("Open", folder, {".nome", ".anom", ".sif", ".slf", ".obj", ".stl", ".glb", ".ply"}, "Open");
  } else if (action == Action::save_as) {
    if (!sessions_.has_scene()) return;
    browser_.open("Save As", folder, {".nome"}, "Save", path.filename().string());
  } else {
    if (!sessions_.has_session()) return;
    browser_.open("Export", folder, {".stl", ".obj", ".glb", ".ply"}, "Save", path.stem().string() + ".stl");
  }
  browser_purpose_ = action;
}

bool Window::can_edit() const {
  return sessions_.has_session() && stage_.shown() && is_editable(stage_.settings().stage);
}

std::optional<bool> Window::sif_pairing() const {
  const Session* session = sessions_.session();
  if (!session || !session->is_sif()) return std::nullopt;
  return session->are_sif_triangles_paired();
}

bool Window::edit(Action action) {
  const std::string name = action_name(action);
  if (!sessions_.has_session()) {
    log_.error(name + ": no file is open");
    return false;
  }
  const bool is_on_selection = action == Action::add_polygon || action == Action::delete_faces ||
                               action == Action::zip || action == Action::toggle_sharp;
  if (is_on_selection && !can_edit()) {
    log_.error(name + ": the " + to_string(stage_.settings().stage) +
               " stage is computed from the scene; switch to the scene or merged stage to edit");
    return false;
  }
  if (action == Action::toggle_sharp && selection_.edges().empty()) {
    log_.error("sharp: select edges first (edge mode: click near an edge)");
    return false;
  }
  if (action == Action::zip && selection_.borders().size() != 2) {
    log_.error("zip: select two borders first (border modes), found " +
               std::to_string(selection_.borders().size()));
    return false;
  }
  if (!sessions_.edit(action, stage_.shown(), selection_, zipper_options_, rims_, sharpness_)) return false;
  // The picked elements went into the edit (or went away with it).
  if (is_on_selection) actions_.run(Action::clear_selection);
  return true;
}

// --------------------------------------------------------------------------------------------- script

void Window::print_state() {
  const StageResult* shown = stage_.shown();
  if (!shown) throw InvalidInputError("state: nothing is shown");
  const TopologyReport& t = shown->topology;
  std::ostringstream line;
  line << "state: " << to_string(shown->stage) << " stage: V " << t.vertices << ", E " << t.edges << ", F "
       << t.faces << ", chi " << t.chi << ", " << (t.orientable ? "orientable" : "non-orientable") << ", "
       << t.borders << " borders, " << t.mobius_edges << " Möbius edges, " << t.components.size()
       << " parts | selection: " << selection_.vertices().size() << " vertices, " << selection_.faces().size()
       << " faces, " << selection_.borders().size() << " borders, " << selection_.instances().size()
       << " instances | faces: " << shown->parts.scene << " scene, " << shown->parts.consolidated
       << " consolidated, " << shown->parts.temporary << " temporary";
  for (const std::unique_ptr<Tool>& tool : tools_)
    if (const std::string text = tool->state_text(tool_context_); !text.empty()) line << " | " << text;
  log_.info(line.str());
}

bool Window::press_key(const std::string& label) {
  if (const auto key = key_of_label(label)) {
    InputFrame frame;
    frame.cursor = last_cursor_;
    frame.keys.push_back({key->first, key->second});
    frame.held = key->second;
    for (const std::unique_ptr<Tool>& tool : tools_)
      if (tool->take_input(tool_context_, frame)) return true;
  }
  return actions_.press(label);
}

void Window::click(glm::dvec2 pixel) {
  if (!stage_.shown()) return;
  for (const std::unique_ptr<Tool>& tool : tools_)
    if (tool->click(tool_context_, pixel)) return;
}

bool Window::double_click(glm::dvec2 pixel) {
  if (!stage_.shown()) return false;
  const auto ray = ray_through_pixel(view_.projection(layout_.viewport), pixel);
  const auto hit = stage_.picking_bvh().cast_nearest(ray);
  if (!hit) {
    log_.info("double-click: no surface under the cursor, the orbit centre stays");
    return false;
  }
  char where[96];
  std::snprintf(where, sizeof where, "orbit centre at (%.6g, %.6g, %.6g)", hit->point.x, hit->point.y,
                hit->point.z);
  log_.info(where);
  view_.orbit_around(hit->point);
  return true;
}

void Window::set_view(double azimuth, double elevation) {
  view_.set_angles(azimuth, elevation);
  frame_all();
}

bool Window::export_mesh(const std::filesystem::path& path) {
  try {
    write_shown_mesh(path);
    return true;
  } catch (const std::exception& e) {
    log_.error(e.what());
    return false;
  }
}

void Window::write_shown_mesh(const std::filesystem::path& path) {
  const Mesh* mesh = stage_.shown_mesh();
  if (!mesh) throw InvalidInputError("export: nothing is shown");
  const std::string ext = lower_extension(path);
  // What a tool makes of the shown stage for export (a placing for print, as `nome export` applies it).
  std::optional<Mesh> placed;
  for (const std::unique_ptr<Tool>& tool : tools_)
    if (!placed) placed = tool->exported(tool_context_, *mesh);
  if (placed) mesh = &*placed;
  if (ext == ".obj")
    write_obj(path, *mesh);
  else if (ext == ".stl")
    write_stl(path, *mesh);
  else if (ext == ".glb")
    write_glb(path, *mesh);
  else if (ext == ".ply")
    write_ply(path, *mesh);
  else
    throw InvalidInputError("export: the file must end in .stl, .obj, .glb or .ply, found '" + path.string() +
                            "'");
  log_.info("exported " + path.string());
}

void Window::set_subdivision(double levels) {
  if (!(levels >= 0 && levels <= 6 && levels == std::floor(levels)))
    throw InvalidInputError("subdiv: expected a level from 0 to 6, found " + std::to_string(levels));
  PipelineSettings& settings = stage_.settings();
  settings.subdivision_levels = int(levels);
  // The offset stages subdivide before offsetting: they stay; otherwise the subdivision is shown.
  if (is_editable(settings.stage)) settings.stage = Stage::subdivided;
}

void Window::set_offset(double distance) {
  if (!(distance >= 0 && std::isfinite(distance)))
    throw InvalidInputError("offset: expected a distance of 0 or more, found " + std::to_string(distance));
  PipelineSettings& settings = stage_.settings();
  if (distance == 0) {
    settings.stage = Stage::subdivided;
    return;
  }
  settings.offset_distance = distance;
  if (settings.stage != Stage::subdivided_offset) settings.stage = Stage::offset;
}

void Window::set_display_color(const std::string& name, glm::vec3 color) {
  if (name == "default") {
    display_.front_color = color;
  } else if (name == "back-faces") {
    display_.back_color = color;
  } else if (name == "selected") {
    display_.selection_color = color;
    refresh_selection();
  } else if (name == "background") {
    display_.background = glm::vec4(color, 1.0f);
  } else if (name == "rim-lines") {
    display_.rim_color = color;
  } else {
    (name == "temporary" ? edit_colors_.temporary : edit_colors_.consolidated) = color;
    paint_faces();
  }
}

void Window::apply_setting(const std::string& name, const std::string& value) {
  PipelineSettings& settings = stage_.settings();
  const auto refuse = [&](const char* expected) {
    throw InvalidInputError("setting " + name + ": expected " + expected + ", found '" + value + "'");
  };
  if (name == "creases") {
    const auto method = parse_crease_method(value);
    if (!method) refuse("uniform or chaikin");
    settings.creases.method = *method;
  } else if (name == "smooth-triangles") {
    if (value != "on" && value != "off") refuse("on or off");
    settings.creases.smooth_triangles = value == "on";
  } else if (name == "border") {
    const auto mode = parse_boundary_mode(value);
    if (!mode) refuse("none, edge-only or edge-and-corner");
    settings.boundary = *mode;
  } else {
    double weight = infinite_sharpness;
    const char* end = value.data() + value.size();
    const bool is_number = value != "infinite" && number_from_chars(value.data(), end, weight).ptr == end;
    if (value != "infinite" && !(is_number && weight >= 0)) refuse("a weight of 0 or more, or infinite");
    sharpness_ = float(std::min(weight, double(infinite_sharpness)));
  }
}

}  // namespace nome::viewer
