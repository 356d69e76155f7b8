#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/ops/pipeline_settings.hpp"

namespace nome::cli {

// --merge --tolerance T --subdiv N --rule classic|report --offset D --subdiv-after M --force
std::vector<OptionSpec> pipeline_option_specs();

// The options as the kernel's pipeline takes them, making `stage`; UsageError for values out of range.
PipelineSettings pipeline_settings(const Arguments& args, Stage stage);

}  // namespace nome::cli
