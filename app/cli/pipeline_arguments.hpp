#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/edit/scene_document.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/ops/pipeline_settings.hpp"

namespace nome::cli {

// --merge --tolerance T --subdiv N --rule classic|report --offset D --subdiv-after M --force
std::vector<OptionSpec> pipeline_option_specs();

// The options as the kernel's pipeline takes them, making `stage`; UsageError for values out of range.
PipelineSettings pipeline_settings(const Arguments& args, Stage stage);

// The scenes' stage blocks (`subdivision ... sd_level N`, `offset ... height H`) where the command line
// gives no --subdiv or --offset of its own: the highest level and the largest distance of all scenes.
// A scene in the successor's dialect that is subdivided is merged first, with a note unless --merge asks.
// An OBJ file's OpenSubdiv options (`t interpolateboundary` unless --boundary is given, `t creasemethod`,
// `t smoothtriangles`).
void apply_obj_tags(const ObjSubdivisionTags& tags, const Arguments& args, PipelineSettings& settings);
void apply_scene_stages(const std::vector<SceneDocument>& scenes, const Arguments& args,
                        PipelineSettings& settings);

}  // namespace nome::cli
