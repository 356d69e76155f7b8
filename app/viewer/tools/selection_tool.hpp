#pragma once

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The selection modes as a tool: a click on the shown stage picks in the current mode (what the other
// tools leave), the script's `mode` and `color`, the Selection section at the top of the controls (the
// modes, the counts, the selected instances' colour) and the mode in the status bar.
class SelectionTool final : public Tool {
 public:
  std::string title() const override { return "Selection"; }
  ToolSide side() const override { return ToolSide::left; }
  bool is_section_open() const override { return true; }
  void draw_section(ToolContext& context) override;
  bool click(ToolContext& context, glm::dvec2 pixel) override;
  std::optional<bool> run_script(ToolContext& context, const ScriptCommand& command) override;
  std::string status_text(const ToolContext& context) const override;

 private:
  // Gives the selected instances a colour; false when refused (logged).
  bool color_instances(ToolContext& context, glm::vec3 color);

  glm::vec3 instance_color_{0.9f, 0.45f, 0.1f};
};

}  // namespace nome::viewer
