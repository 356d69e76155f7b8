#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/pipeline.hpp"

namespace nome::cli {

// --subdiv N --rule classic|report --offset D --subdiv-after M --force
std::vector<OptionSpec> pipeline_option_specs();

// The options as the kernel's pipeline takes them; UsageError for values out of range.
PipelineOptions pipeline_options(const Arguments& args);

// Runs the pipeline on the merged mesh, printing its warnings to stderr; without `with_offset` it stops
// after the subdivision (nome render --stage subdivided).
Mesh run_pipeline(const Mesh& mesh, const Arguments& args, bool with_offset = true);

}  // namespace nome::cli
