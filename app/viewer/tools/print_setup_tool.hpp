#pragma once

#include <optional>

#include "nome/ops/print_placement.hpp"

namespace nome::viewer {

// The "Print preparation" section: scale to a height or a largest dimension (mm) and rest on the flattest
// large face or the selected face (`selected_face`, a face of the shown stage). The setup is kept with the
// scene and applied by File > Export and `nome export`. Returns the setup when the user changed it.
std::optional<PrintPlacementOptions> draw_print_setup_section(const PrintPlacementOptions& setup,
                                                              std::optional<Index> selected_face);

}  // namespace nome::viewer
