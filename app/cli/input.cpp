#include "cli/input.hpp"

#include <iostream>

#include "cli/pipeline_arguments.hpp"
#include "cli/scene_input.hpp"
#include "nome/error.hpp"
#include "nome/ops/pipeline.hpp"

namespace nome::cli {

void print_warnings(const std::vector<std::string>& warnings) {
  constexpr size_t max_merge_warnings = 10;
  size_t merge_warnings = 0;
  for (const std::string& w : warnings) {
    const bool is_merge = w.rfind("merge: ", 0) == 0;
    if (is_merge && ++merge_warnings > max_merge_warnings) continue;
    std::cerr << "nome: warning: " << w << "\n";
  }
  if (merge_warnings > max_merge_warnings)
    std::cerr << "nome: warning: merge: " << merge_warnings - max_merge_warnings << " more merges skipped\n";
}

std::vector<OptionSpec> input_options() {
  std::vector<OptionSpec> options = {
      {"--set", "", "BANK_PARAM=VALUE", "override a slider of a scene (repeatable)", true},
      {"--quads", "", "", "pair the triangles of .sif files into quads where convex and nearly planar"},
      {"--dialect", "", "2016|jipcad",
       "read scenes in this spelling (default: as their statements say; funnel and tunnel's arguments "
       "differ)"},
      {"--quiet", "-q", "", "no progress bar (there is none either when stderr is not a terminal)"}};
  for (OptionSpec& o : pipeline_option_specs()) options.push_back(std::move(o));
  return options;
}

Stage stage_argument(const std::string& name) {
  if (const auto stage = parse_stage(name)) return *stage;
  throw UsageError("--stage expects scene, merged, subdivided, offset or subdivided-offset, found '" + name +
                   "'");
}

LoadedInput run_input(const Arguments& args, Stage last, const Progress& progress, bool builds_last_level) {
  if (args.positionals().empty()) throw UsageError("no input FILE given");
  InputFiles input = read_input_files(args);
  LoadedInput loaded;
  PipelineSettings& settings = loaded.settings;
  settings = pipeline_settings(args, last);
  apply_scene_stages(input.scenes, args, settings);
  apply_obj_tags(input.obj_tags, args, settings);
  if (settings.levels_before() == 0 && settings.levels_after() == 0) {
    // Nothing refined: the options stay the mesh's, for an OBJ written from it.
    if (settings.boundary != BoundaryMode::edge_only) loaded.kept_tags.boundary = settings.boundary;
    if (settings.creases.method != CreaseMethod::uniform)
      loaded.kept_tags.crease_method = settings.creases.method;
    if (settings.creases.smooth_triangles) loaded.kept_tags.smooth_triangles = true;
  }
  loaded.pipeline.set_input(std::move(input.geometry));
  loaded.pipeline.set_progress(progress);
  try {
    if (builds_last_level)
      loaded.pipeline.run(loaded.settings);
    else
      loaded.pipeline.run_before_surface(loaded.settings);
  } catch (const BudgetError& e) {
    throw BudgetError(std::string(e.what()) + "; use --force to compute it anyway");
  }
  print_warnings(loaded.pipeline.warnings());
  loaded.scenes = std::move(input.scenes);
  return loaded;
}

}  // namespace nome::cli
