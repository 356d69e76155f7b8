#pragma once

#include <optional>

#include "nome/ops/print_placement.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The "Print preparation" section: scale to a height or a largest dimension (mm) and rest on the flattest
// large face or the selected face (`selected_face`, a face of the shown stage). The setup is kept with the
// scene and applied by File > Export and `nome export`. Returns the setup when the user changed it.
std::optional<PrintPlacementOptions> draw_print_setup_section(const PrintPlacementOptions& setup,
                                                              std::optional<Index> selected_face);

// The print preparation as a tool: its section edits the scene's setup, and File > Export writes the
// shown stage placed by it.
class PrintSetupTool final : public Tool {
 public:
  std::string title() const override { return "Print preparation"; }
  void draw_section(ToolContext& context) override;
  std::optional<Mesh> exported(const ToolContext& context, const Mesh& shown) const override;
};

}  // namespace nome::viewer
