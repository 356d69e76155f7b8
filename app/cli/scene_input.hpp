#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/edit/scene_document.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/ops/pipeline_input.hpp"
#include "nome/scene/scene.hpp"

namespace nome::cli {

// What the FILE arguments hold: the scenes (.nome/.nom/.slf, each .anom applied to the scene before it)
// with their --set overrides applied, each read into the document the viewer edits, so that a file's
// edits (consolidated and deleted faces, sharp edges) are applied one way; and the pipeline's input: one
// part per scene (its top-level instances as a disjoint union, with its edits) and per flat file (.obj,
// .stl, .sif), each named for its file.
struct InputFiles {
  std::vector<SceneDocument> scenes;
  PipelineInput geometry;
  ObjSubdivisionTags obj_tags;  // the .obj files' OpenSubdiv options (a later file's win)
};

InputFiles read_input_files(const Arguments& args);

// "BANK_PARAM=VALUE" of --set, applied to every scene that has the parameter.
void apply_overrides(std::vector<SceneDocument>& scenes, const std::vector<std::string>& overrides);

}  // namespace nome::cli
