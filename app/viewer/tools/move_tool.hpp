#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "nome/edit/scene_drag.hpp"
#include "nome/query/screen_projection.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// Sculpting by hand (Blender's G): G, or a press on an arrow of the handle drawn on the selection, drags
// the selected vertices (vertex mode) or instances (instance mode). The scene's text follows: the numbers
// that place them are rewritten, or the sliders that place them are solved for (SceneDrag), live through
// the positions-only path. While a drag lasts: X, Y or Z keeps it on that axis, Shift+X/Y/Z on the plane
// without it (again: free); Ctrl puts the offset on a grid; typing a number moves exactly that far (along
// the axis; X without one); a click or Enter keeps it (one undo step), Esc or a right click cancels. The
// `drag` script command does the same without the mouse; `drag-hold` leaves the drag held (a key ends it).
class MoveTool final : public Tool {
 public:
  void bind(ToolContext& context) override;
  bool take_input(ToolContext& context, const InputFrame& input) override;
  void draw_overlay(ToolContext& context) override;
  std::optional<bool> run_script(ToolContext& context, const ScriptCommand& command) override;
  std::string status_text(const ToolContext& context) const override;
  std::string state_text(const ToolContext& context) const override;
  bool is_animating() const override { return drag_.has_value(); }

  bool is_dragging() const { return drag_.has_value(); }
  // The offset of the drag in progress (world units).
  Vec3 offset() const { return drag_ ? drag_->offset : Vec3(0.0); }

 private:
  struct Drag {
    Vec3 centre{0.0};
    glm::dvec2 press{0.0};
    int axis = -1;          // 0 x, 1 y, 2 z; -1 free
    bool is_plane = false;  // on the plane without the axis
    bool is_held = false;   // begun on the handle: the release keeps it
    std::string typed;      // a distance being typed
    Vec3 offset{0.0};
    bool is_scripted = false;  // its offset is a script's (drag-hold), not the cursor's
    DragSelection selection;
  };

  // The selection as a drag names it; throws InvalidInputError when nothing draggable is selected.
  DragSelection dragged(const ToolContext& context) const;
  bool begin(ToolContext& context, const DragSelection& selection, glm::dvec2 cursor, int axis, bool is_held);
  // A script's `drag` or `drag-hold`: the selection it names and the offset it gives.
  bool run_drag(ToolContext& context, const ScriptCommand& command);
  void follow(ToolContext& context, glm::dvec2 cursor, bool snaps);
  void finish(ToolContext& context, bool keeps);
  void take_key(ToolContext& context, const KeyPress& key);
  Vec3 offset_at(const ToolContext& context, glm::dvec2 cursor) const;
  // Where the handle stands (the selection's centre, where the drag put it), if there is a selection to drag.
  std::optional<Vec3> handle_centre(const ToolContext& context) const;
  // The arrow of the handle under the cursor: 0, 1, 2, or -1.
  int arrow_under(const ToolContext& context, glm::dvec2 cursor) const;
  std::string moved_text() const;

  std::optional<Drag> drag_;
};

}  // namespace nome::viewer
