#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/edit/scene_document.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/mesh/mesh.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/stage.hpp"

namespace nome::cli {

// The options every command that reads geometry shares.
std::vector<OptionSpec> input_options();

// Parses a --stage value (UsageError for an unknown one).
Stage stage_argument(const std::string& name);

// The pipeline after a run of the FILE arguments up to a stage, kept for a caller that also wants an
// earlier stage (the print check reads the surface before the offset).
struct LoadedInput {
  Pipeline pipeline;
  PipelineSettings settings;
  std::vector<SceneDocument> scenes;
  // When nothing is subdivided: the subdivision options that differ from the defaults, for write_obj to
  // keep.
  ObjSubdivisionTags kept_tags;
};

// Prints a pipeline's warnings; merge warnings can be many (one per skipped pair): the first few, then a
// count.
void print_warnings(const std::vector<std::string>& warnings);

// Reads the FILE arguments and runs the pipeline up to `last`, printing its warnings; its stages report
// to `progress` (also in later runs of the returned pipeline). Unless `builds_last_level`, a last stage
// that a writer can stream (a subdivision or an offset) is left to the caller (Pipeline::run_surface,
// run_to_last_subdivision).
LoadedInput run_input(const Arguments& args, Stage last, const Progress& progress = {},
                      bool builds_last_level = true);

}  // namespace nome::cli
