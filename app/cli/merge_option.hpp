#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/mesh.hpp"

namespace nome::cli {

// --merge and --tolerance T (DESIGN.md, "The command line").
std::vector<OptionSpec> merge_options();

// With --merge, glues the coincident boundary edges of all parts (every input file, every top-level
// instance); merges skipped to keep a 2-manifold are listed on stderr. Without it, the mesh as is.
Mesh apply_merge_option(Mesh mesh, const Arguments& args);

}  // namespace nome::cli
