#include "viewer/tools/tool_list.hpp"

#include "viewer/tools/measure_tool.hpp"
#include "viewer/tools/move_tool.hpp"
#include "viewer/tools/print_check_tool.hpp"
#include "viewer/tools/print_setup_tool.hpp"
#include "viewer/tools/section_tool.hpp"
#include "viewer/tools/selection_tool.hpp"
#include "viewer/tools/text_pane_tool.hpp"
#include "viewer/tools/turntable_tool.hpp"

namespace nome::viewer {

// One line a tool. Measuring comes before selecting: while a measuring mode is on, clicks measure.
std::vector<std::unique_ptr<Tool>> make_tools() {
  std::vector<std::unique_ptr<Tool>> tools;
  tools.push_back(std::make_unique<MoveTool>());
  tools.push_back(std::make_unique<PrintCheckTool>());
  tools.push_back(std::make_unique<PrintSetupTool>());
  tools.push_back(std::make_unique<MeasureTool>());
  tools.push_back(std::make_unique<SectionTool>());
  tools.push_back(std::make_unique<TurntableTool>());
  tools.push_back(std::make_unique<SelectionTool>());
  tools.push_back(std::make_unique<TextPaneTool>());
  return tools;
}

}  // namespace nome::viewer
