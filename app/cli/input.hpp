#pragma once

#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/scene/scene.hpp"

namespace nome::cli {

// The options every command that reads geometry shares (DESIGN.md, "The command line").
std::vector<OptionSpec> input_options();

// The pipeline's stages in order (DESIGN.md); `nome render --stage` shows an earlier one than the last.
enum class Stage { scene, merged, subdivided, offset };

// Parses a --stage value; refuses (UsageError) a stage whose kernel feature has not landed yet.
Stage parse_stage(const std::string& name);

// Reads the FILE arguments (several become parts of one mesh) and runs the pipeline the options ask for.
Mesh load_input(const Arguments& args);
// The same, stopping after `last` (the stages the options do not ask for pass the mesh through).
Mesh load_input(const Arguments& args, Stage last);
// The same, handing back the scenes read (.nome, .slf) through `scenes`.
Mesh load_input(const Arguments& args, Stage last, std::vector<scene::Scene>* scenes);

}  // namespace nome::cli
