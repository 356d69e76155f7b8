#pragma once

#include <cstddef>
#include <optional>

#include "viewer/commands/actions.hpp"
#include "viewer/tools/print_check_job.hpp"

namespace nome::viewer {

// The "Print check" section (in the right sidebar): the check's button and settings, its verdict and
// counts, and the worst places; returns the place the user clicked, to be framed.
std::optional<std::size_t> draw_print_check_section(const ActionRegistry& actions, PrintCheckView& view,
                                                    bool is_current);

}  // namespace nome::viewer
