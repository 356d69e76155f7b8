#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/mesh.hpp"

namespace nome::cli {

// The options every command that reads geometry shares (DESIGN.md, "The command line").
std::vector<OptionSpec> input_options();

// Reads the FILE arguments (several become parts of one mesh) and runs the pipeline the options ask for.
Mesh load_input(const Arguments& args);

}  // namespace nome::cli
