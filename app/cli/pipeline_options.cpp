#include "cli/pipeline_options.hpp"

#include <algorithm>
#include <iostream>
#include <thread>

#include "nome/error.hpp"

namespace nome::cli {

std::vector<OptionSpec> pipeline_option_specs() {
  return {
      {"--subdiv", "", "N", "Catmull-Clark subdivision levels (default 0)"},
      {"--rule", "", "RULE",
       "smooth-vertex rule: classic (Catmull-Clark, default) or report (the 2016 report's)"},
      {"--offset", "", "D", "thicken into a closed solid, D on each side of the surface (D > 0)"},
      {"--subdiv-after", "", "M", "Catmull-Clark levels after --offset, to round the rims (default 0)"},
      {"--force", "", "",
       "compute results whose estimated size exceeds the memory budget (4 GB), expand scenes of more than "
       "1000000 instances"},
  };
}

PipelineOptions pipeline_options(const Arguments& args) {
  PipelineOptions o;
  o.subdivision_levels = args.int_value("--subdiv", 0, 0, 12);
  o.subdivision_after = args.int_value("--subdiv-after", 0, 0, 12);
  if (const auto rule = args.value("--rule")) {
    if (*rule == "classic")
      o.rule = SubdivisionRule::classic;
    else if (*rule == "report")
      o.rule = SubdivisionRule::report;
    else
      throw UsageError("--rule expects classic or report, found '" + *rule + "'");
  }
  if (args.has("--offset")) {
    o.offset_distance = args.double_value("--offset", 0.0);
    if (o.offset_distance <= 0.0)
      throw UsageError("--offset expects a positive distance, found " + *args.value("--offset"));
  }
  if (o.subdivision_after > 0 && !args.has("--offset")) throw UsageError("--subdiv-after needs --offset");
  o.force = args.has("--force");
  o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  return o;
}

Mesh run_pipeline(const Mesh& mesh, const Arguments& args, bool with_offset) {
  PipelineOptions options = pipeline_options(args);
  if (!with_offset) options.offset_distance = 0, options.subdivision_after = 0;
  Pipeline pipeline;
  try {
    pipeline.run(mesh, options);
  } catch (const BudgetError& e) {
    throw BudgetError(std::string(e.what()) + "; use --force to compute it anyway");
  }
  for (const std::string& warning : pipeline.warnings()) std::cerr << "nome: warning: " << warning << "\n";
  return pipeline.take_result(mesh);
}

}  // namespace nome::cli
