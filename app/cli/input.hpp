#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/stage.hpp"
#include "nome/scene/scene.hpp"

namespace nome::cli {

// The options every command that reads geometry shares (DESIGN.md, "The command line").
std::vector<OptionSpec> input_options();

// Parses a --stage value (UsageError for an unknown one).
Stage stage_argument(const std::string& name);

// Reads the FILE arguments (several become parts of one mesh) and runs the kernel's pipeline up to
// `last` with the options' settings; the scenes read (.nome, .slf) come back through `scenes`.
// When nothing is subdivided, `kept_tags` receives the subdivision options that differ from the
// defaults, for write_obj to keep.
Mesh load_input(const Arguments& args, Stage last = Stage::subdivided_offset,
                std::vector<scene::Scene>* scenes = nullptr, ObjSubdivisionTags* kept_tags = nullptr);

}  // namespace nome::cli
