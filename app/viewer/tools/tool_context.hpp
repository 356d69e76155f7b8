#pragma once

#include <functional>
#include <utility>

#include <glm/vec3.hpp>

#include "render/display_settings.hpp"
#include "viewer/commands/actions.hpp"
#include "viewer/layout.hpp"
#include "viewer/message_log.hpp"
#include "viewer/platform.hpp"
#include "viewer/session/session_controller.hpp"
#include "viewer/session/stage_view.hpp"
#include "viewer/view/rim_picking.hpp"
#include "viewer/view/selection.hpp"
#include "viewer/view/view_controller.hpp"

namespace nome::viewer {

// What a tool may reach of its window: the document, the shown stage, the selection, the camera, the
// action table, the display, the layout, and the window's two ways of showing a change.
struct ToolContext {
  MessageLog& log;
  SessionController& sessions;
  StageView& stage;
  Selection& selection;
  ViewController& view;
  ActionRegistry& actions;
  render::DisplaySettings& display;
  LayoutSettings& layout_settings;
  const ScreenLayout& layout;  // this frame's places; the viewport's is where clicks land
  const PickableRims& rims;
  const Platform& platform;
  const glm::dvec3& shown_low;  // the shown stage's bounding box
  const glm::dvec3& shown_high;
  // Draws the selection's and the tools' markers again (after the selection or a marker changed).
  std::function<void()> refresh_selection;
  // Paints the shown stage's faces again (after a tool's paints changed).
  std::function<void()> paint_faces;
  // Takes the document's latest state to the screen (after a tool changed it).
  std::function<void()> update_stage;
};

}  // namespace nome::viewer
