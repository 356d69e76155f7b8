#include "viewer/tools/move_tool.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <glm/geometric.hpp>

#include "nome/error.hpp"

namespace nome::viewer {
namespace {

const char* const axis_names[] = {"X", "Y", "Z"};
const ImU32 axis_colors[] = {IM_COL32(220, 60, 50, 255), IM_COL32(70, 180, 60, 255),
                             IM_COL32(60, 110, 230, 255)};
constexpr float arrow_pixels = 70.0f;  // an arrow's length on screen
constexpr double arrow_reach = 8.0;    // how near the cursor must be to take one

bool has(KeyModifier held, KeyModifier m) {
  return (int(held) & int(m)) != 0;
}

Vec3 unit(int axis) {
  Vec3 e(0.0);
  e[axis] = 1.0;
  return e;
}

// Where the ray meets the plane, if it does (not parallel to it).
std::optional<Vec3> meet_plane(const Ray& ray, const Vec3& point, const Vec3& normal) {
  const double along = glm::dot(ray.direction, normal);
  if (std::abs(along) < 1e-12 * glm::length(ray.direction)) return std::nullopt;
  return ray.origin + ray.direction * (glm::dot(point - ray.origin, normal) / along);
}

// The parameter s of the point centre + s * axis nearest the ray.
std::optional<double> nearest_on_axis(const Ray& ray, const Vec3& centre, const Vec3& axis) {
  const Vec3 d = glm::normalize(ray.direction);
  const Vec3 w = centre - ray.origin;
  const double b = glm::dot(axis, d);
  const double denominator = 1.0 - b * b;
  if (denominator < 1e-9) return std::nullopt;  // the axis points at the eye
  return (b * glm::dot(w, d) - glm::dot(w, axis)) / denominator;
}

// The distance from p to the segment [a, b] (pixels).
double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

// What a script names: a vertex by any unique suffix of its name, a copied vertex (a consolidated mesh's) by
// its full name, else an instance by its path; InvalidInputError for none of them.
DragSelection named_selection(const scene::Scene& scene, const std::string& what) {
  try {
    return {{scene.resolve_vertex_name(what)}, {}};
  } catch (const scene::SceneError& not_vertex) {
    if (scene.find_placed_vertex(what)) return {{what}, {}};
    try {
      scene.instance_origin(what);
    } catch (const Error&) {
      throw InvalidInputError("drag: '" + what + "' is no instance path, and as a vertex: " +
                              not_vertex.diagnostics().front().message);
    }
    return {{}, {what}};
  }
}

}  // namespace

void MoveTool::bind(ToolContext& context) {
  context.actions.bind(Action::move, [this, &context] {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    try {
      return begin(context, dragged(context), {mouse.x, mouse.y}, -1, false);
    } catch (const Error& e) {
      context.log.error(e.what());
      return false;
    }
  });
}

DragSelection MoveTool::dragged(const ToolContext& context) const {
  const Selection& selection = context.selection;
  DragSelection out;
  if (selection.mode() == SelectionMode::instance) {
    out.instances = selection.instances();
  } else if (selection.mode() == SelectionMode::vertex && context.stage.shown()) {
    const Mesh& mesh = *context.stage.shown()->mesh;
    for (const Index v : selection.vertices()) {
      std::string name = context.rims.name(mesh, v);
      if (name.empty() || !context.sessions.scene() || !context.sessions.scene()->find_placed_vertex(name))
        throw InvalidInputError(
            "drag: vertex " + (name.empty() ? std::to_string(v) : "'" + name + "'") +
            " is no vertex of the scene's statements (pick vertices on the scene or merged "
            "stage)");
      out.vertices.push_back(std::move(name));
    }
  }
  if (out.vertices.empty() && out.instances.empty())
    throw InvalidInputError(
        "drag: select vertices (vertex mode) or instances (instance mode) first, then press G");
  return out;
}

bool MoveTool::begin(ToolContext& context, const DragSelection& selection, glm::dvec2 cursor, int axis,
                     bool is_held) {
  if (!context.sessions.begin_drag(selection)) return false;
  drag_ =
      Drag{context.sessions.drag()->centre(), cursor, axis, false, is_held, {}, Vec3(0.0), false, selection};
  context.log.info("drag: " + context.sessions.drag()->description() +
                   (is_held ? " (release to keep)" : " (click or Enter keeps, Esc cancels)"));
  return true;
}

Vec3 MoveTool::offset_at(const ToolContext& context, glm::dvec2 cursor) const {
  const Drag& d = *drag_;
  if (!d.typed.empty()) {
    char* end = nullptr;
    const double distance = std::strtod(d.typed.c_str(), &end);
    if (end == d.typed.c_str() || !std::isfinite(distance)) return Vec3(0.0);
    return distance * unit(d.axis < 0 ? 0 : d.axis);
  }
  const ScreenProjection projection = context.view.projection(context.layout.viewport);
  const Ray now = ray_through_pixel(projection, cursor), then = ray_through_pixel(projection, d.press);
  if (d.axis >= 0 && !d.is_plane) {
    const auto a = nearest_on_axis(then, d.centre, unit(d.axis)),
               b = nearest_on_axis(now, d.centre, unit(d.axis));
    return a && b ? (*b - *a) * unit(d.axis) : d.offset;
  }
  // Free: the plane through the centre facing the eye; Shift+axis: the plane across that axis.
  const auto centre_pixel = project_to_pixel(projection, d.centre);
  const Vec3 normal = d.axis >= 0    ? unit(d.axis)
                      : centre_pixel ? ray_through_pixel(projection, glm::dvec2(*centre_pixel)).direction
                                     : then.direction;
  const auto a = meet_plane(then, d.centre, normal), b = meet_plane(now, d.centre, normal);
  return a && b ? *b - *a : d.offset;
}

void MoveTool::follow(ToolContext& context, glm::dvec2 cursor, bool snaps) {
  if (drag_->is_scripted && drag_->typed.empty()) return;
  Vec3 offset = offset_at(context, cursor);
  if (snaps && drag_->typed.empty()) {
    // A grid a tenth of the shown stage's size, rounded down to a power of ten (0.1 for a model 1 to 10
    // across).
    const double size = glm::distance(context.shown_low, context.shown_high);
    const double grid = size > 0 ? std::pow(10.0, std::floor(std::log10(size)) - 1.0) : 0.1;
    for (int k = 0; k < 3; ++k) offset[k] = std::round(offset[k] / grid) * grid;
  }
  if (offset == drag_->offset) return;
  drag_->offset = offset;
  if (context.sessions.drag_to(offset)) context.update_stage();
}

void MoveTool::finish(ToolContext& context, bool keeps) {
  if (!drag_) return;
  if (keeps)
    context.sessions.end_drag();
  else
    context.sessions.cancel_drag();
  if (!keeps) context.log.info("drag cancelled");
  drag_.reset();
  context.update_stage();
}

void MoveTool::take_key(ToolContext& context, const KeyPress& key) {
  Drag& d = *drag_;
  if (key.key >= GLFW_KEY_X && key.key <= GLFW_KEY_Z) {
    const int axis = key.key - GLFW_KEY_X;
    const bool is_plane = has(key.modifiers, KeyModifier::shift);
    // The same constraint again frees the drag, as in Blender.
    const bool is_same = d.axis == axis && d.is_plane == is_plane;
    d.axis = is_same ? -1 : axis;
    d.is_plane = !is_same && is_plane;
    return;
  }
  const bool is_digit = (key.key >= GLFW_KEY_0 && key.key <= GLFW_KEY_9) ||
                        (key.key >= GLFW_KEY_KP_0 && key.key <= GLFW_KEY_KP_9);
  if (is_digit) {
    d.typed += char('0' + (key.key >= GLFW_KEY_KP_0 ? key.key - GLFW_KEY_KP_0 : key.key - GLFW_KEY_0));
  } else if (key.key == GLFW_KEY_PERIOD || key.key == GLFW_KEY_KP_DECIMAL) {
    d.typed += '.';
  } else if (key.key == GLFW_KEY_MINUS || key.key == GLFW_KEY_KP_SUBTRACT) {
    // A minus anywhere turns the distance round.
    d.typed = d.typed.starts_with('-') ? d.typed.substr(1) : "-" + d.typed;
  } else if (key.key == GLFW_KEY_BACKSPACE && !d.typed.empty()) {
    d.typed.pop_back();
  } else if (key.key == GLFW_KEY_ENTER || key.key == GLFW_KEY_KP_ENTER) {
    finish(context, true);
  } else if (key.key == GLFW_KEY_ESCAPE) {
    finish(context, false);
  }
}

bool MoveTool::take_input(ToolContext& context, const InputFrame& input) {
  if (!drag_) {
    // A press on an arrow of the handle begins a drag along it.
    if (!input.is_pressed[0] || input.is_over_panel) return false;
    const int axis = arrow_under(context, input.cursor);
    if (axis < 0) return false;
    try {
      begin(context, dragged(context), input.cursor, axis, true);
    } catch (const Error& e) {
      context.log.error(e.what());
    }
    return true;
  }
  for (const KeyPress& key : input.keys) {
    take_key(context, key);
    if (!drag_) return true;
  }
  if (input.is_pressed[1]) {
    finish(context, false);
    return true;
  }
  follow(context, input.cursor, has(input.held, KeyModifier::control));
  if (drag_->is_held ? !input.is_down[0] : input.is_pressed[0]) finish(context, true);
  return true;
}

std::optional<Vec3> MoveTool::handle_centre(const ToolContext& context) const {
  const Selection& selection = context.selection;
  const StageResult* shown = context.stage.shown();
  const scene::Scene* scene = context.sessions.scene();
  if (!shown || !scene) return std::nullopt;
  Vec3 sum(0.0);
  std::size_t count = 0;
  if (drag_) {
    // Where the drag has put them (sliders may stop short of the drop).
    for (const std::string& name : drag_->selection.vertices)
      if (const auto v = scene->find_placed_vertex(name)) sum += scene->position(*v), ++count;
    for (const std::string& path : drag_->selection.instances) {
      try {
        sum += scene->instance_origin(path).position, ++count;
      } catch (const Error&) {
        continue;
      }
    }
  } else if (selection.mode() == SelectionMode::vertex) {
    for (const Index v : selection.vertices()) sum += context.rims.position(*shown->mesh, v), ++count;
  } else if (selection.mode() == SelectionMode::instance) {
    for (const std::string& path : selection.instances()) {
      try {
        sum += scene->instance_origin(path).position, ++count;
      } catch (const Error&) {
        continue;  // an instance the last text no longer has
      }
    }
  }
  if (count == 0) return std::nullopt;
  return sum / double(count);
}

int MoveTool::arrow_under(const ToolContext& context, glm::dvec2 cursor) const {
  const auto centre = handle_centre(context);
  if (!centre) return -1;
  const ScreenProjection projection = context.view.projection(context.layout.viewport);
  const auto origin = project_to_pixel(projection, *centre);
  if (!origin) return -1;
  const double scale = std::max(glm::distance(context.shown_low, context.shown_high), 1e-9) * 1e-3;
  for (int axis = 0; axis < 3; ++axis) {
    const auto tip = project_to_pixel(projection, *centre + scale * unit(axis));
    if (!tip) continue;
    const glm::dvec2 a(*origin), direction = glm::dvec2(*tip) - a;
    if (glm::length(direction) < 1e-9) continue;
    const glm::dvec2 b = a + glm::normalize(direction) * double(arrow_pixels);
    if (segment_distance(cursor, a + 0.25 * (b - a), b) < arrow_reach) return axis;
  }
  return -1;
}

void MoveTool::draw_overlay(ToolContext& context) {
  const auto centre = handle_centre(context);
  if (!centre) return;
  const ScreenProjection projection = context.view.projection(context.layout.viewport);
  const auto origin = project_to_pixel(projection, *centre);
  if (!origin) return;
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const ImVec2 o(float(origin->x), float(origin->y));
  const double scale = std::max(glm::distance(context.shown_low, context.shown_high), 1e-9) * 1e-3;
  for (int axis = 0; axis < 3; ++axis) {
    const auto tip = project_to_pixel(projection, *centre + scale * unit(axis));
    if (!tip) continue;
    glm::dvec2 direction = glm::dvec2(*tip) - glm::dvec2(*origin);
    if (glm::length(direction) < 1e-9) continue;
    direction = glm::normalize(direction);
    const bool is_active = drag_ && drag_->axis == axis;
    const bool is_dimmed = drag_ && drag_->axis >= 0 && !is_active;
    const ImU32 color = is_dimmed ? (axis_colors[axis] & 0x60FFFFFFu) : axis_colors[axis];
    const ImVec2 end(o.x + float(direction.x) * arrow_pixels, o.y + float(direction.y) * arrow_pixels);
    const ImVec2 side(-float(direction.y) * 6.0f, float(direction.x) * 6.0f);
    const ImVec2 base(end.x - float(direction.x) * 14.0f, end.y - float(direction.y) * 14.0f);
    list->AddLine(o, base, color, is_active ? 4.0f : 2.5f);
    list->AddTriangleFilled(end, ImVec2(base.x + side.x, base.y + side.y),
                            ImVec2(base.x - side.x, base.y - side.y), color);
    list->AddText(ImVec2(end.x + 4.0f, end.y - 8.0f), color, axis_names[axis]);
  }
  list->AddCircleFilled(o, 4.0f, IM_COL32(255, 255, 255, 230));
  if (!drag_) return;
  // Where the drag began, joined to where it was dropped (a ring there when the selection stopped short).
  const ImU32 trail = IM_COL32(250, 200, 60, 230);
  const auto start = project_to_pixel(projection, drag_->centre);
  const auto drop = project_to_pixel(projection, drag_->centre + drag_->offset);
  if (start && drop) {
    const ImVec2 a(float(start->x), float(start->y)), b(float(drop->x), float(drop->y));
    list->AddLine(a, b, trail, 1.5f);
    list->AddCircle(a, 5.0f, trail);
    list->AddCircle(b, 7.0f, trail, 0, 2.0f);
  }
  list->AddText(ImVec2(o.x + 10.0f, o.y + 8.0f), IM_COL32(250, 200, 60, 255), moved_text().c_str());
}

std::string MoveTool::moved_text() const {
  if (!drag_) return {};
  char text[96];
  const Drag& d = *drag_;
  if (d.axis >= 0 && !d.is_plane) {
    std::snprintf(text, sizeof text, "%.4g along %s", d.offset[d.axis], axis_names[d.axis]);
  } else {
    std::snprintf(text, sizeof text, "%.4g (%.4g %.4g %.4g)%s%s", glm::length(d.offset), d.offset.x,
                  d.offset.y, d.offset.z, d.is_plane ? " across " : "", d.is_plane ? axis_names[d.axis] : "");
  }
  return d.typed.empty() ? text : std::string(text) + " [typed " + d.typed + "]";
}

std::string MoveTool::status_text(const ToolContext& context) const {
  if (!drag_ || !context.sessions.drag()) return {};
  std::string text = "moving " + moved_text() + ": " + context.sessions.drag()->description();
  if (const DragStep* step = context.sessions.drag_step(); step && step->slider_miss > 1e-6) {
    char miss[48];
    std::snprintf(miss, sizeof miss, " (the sliders stop %.3g short)", step->slider_miss);
    text += miss;
  }
  return text;
}

std::string MoveTool::state_text(const ToolContext&) const {
  return drag_ ? "drag: " + moved_text() : std::string();
}

std::optional<bool> MoveTool::run_script(ToolContext& context, const ScriptCommand& command) {
  if (command.kind != ScriptCommand::Kind::drag && command.kind != ScriptCommand::Kind::drag_hold)
    return std::nullopt;
  return run_drag(context, command);
}

bool MoveTool::run_drag(ToolContext& context, const ScriptCommand& command) {
  if (drag_) finish(context, true);
  const std::string& what = command.words[0];
  const scene::Scene* scene = context.sessions.scene();
  const DragSelection selection =
      what == "selection" || !scene ? dragged(context) : named_selection(*scene, what);
  Vec3 offset(0.0);
  int axis = -1;
  if (command.words.size() == 2) {
    axis = command.words[1][0] - 'x';
    offset[axis] = command.numbers[0];
  } else {
    offset = Vec3(command.numbers[0], command.numbers[1], command.numbers[2]);
  }
  if (!begin(context, selection, glm::dvec2(0.0), axis, false)) return false;
  drag_->is_scripted = true;
  drag_->offset = offset;
  const bool is_moved = context.sessions.drag_to(offset);
  if (!is_moved || command.kind == ScriptCommand::Kind::drag) finish(context, is_moved);
  context.update_stage();
  return is_moved;
}

}  // namespace nome::viewer
