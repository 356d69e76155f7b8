#pragma once

#include <glm/vec3.hpp>

#include "nome/mesh/mesh.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The section plane of the view (C, View > Section): perpendicular to an axis or to the view direction
// through the view's centre, moved along its normal; what lies beyond it is cut away and a solid's cut is
// filled in the section colour.
struct SectionState {
  enum class Orientation { x, y, z, view };
  bool is_on = false;
  Orientation orientation = Orientation::z;
  double offset = 0.0;  // along the normal, from the middle of the shown mesh (or the view's centre)

  bool operator==(const SectionState&) const = default;
};

// The Section section of the sidebar: on/off, the orientation and the position along the normal within
// the shown mesh's extent (`low`..`high`, its bounding box).
void draw_section_panel(SectionState& state, const glm::dvec3& low, const glm::dvec3& high);

// The display's plane for the state (zero when off): `centre` is the middle of the shown mesh; a view
// section goes through the camera's target. `is_solid`: the shown stage is a closed solid (an offset),
// whose cut is filled.
void apply_section(const SectionState& state, const render::Camera& camera, const glm::dvec3& centre,
                   bool is_solid, render::DisplaySettings& display);

// The section plane as a tool: its key (C), its sidebar section, and the plane set on the display each
// frame.
class SectionTool final : public Tool {
 public:
  std::string title() const override { return "Section"; }
  void bind(ToolContext& context) override;
  void before_draw(ToolContext& context) override;
  void draw_section(ToolContext& context) override;

  const SectionState& state() const { return state_; }

 private:
  SectionState state_;
};

}  // namespace nome::viewer
