#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "nome/io/three_mf.hpp"
#include "nome/ops/print_placement.hpp"

namespace nome::cli {

// --fit-height, --fit-size and --rest-on, for `nome export`.
std::vector<OptionSpec> print_setup_options();

// A length with an optional unit ("60mm", "6cm", "2.5in", "0.06m"; a bare number is mm) in millimetres.
// Throws UsageError naming `option` for anything else or a length that is not positive.
double length_in_mm(const std::string& text, const std::string& option);

// How many millimetres one model unit stands for.
double millimeters_per(LengthUnit unit);

// The print preparation of an export: the scene's kept `printsetup` (if any) with the options on top, the
// sizes in model units of `unit`.
PrintPlacementOptions print_setup_argument(const Arguments& parsed, std::optional<PrintPlacementOptions> kept,
                                           LengthUnit unit);

}  // namespace nome::cli
