#include "cli/pipeline_arguments.hpp"

#include <algorithm>
#include <iostream>
#include <thread>

#include "nome/error.hpp"

namespace nome::cli {

std::vector<OptionSpec> pipeline_option_specs() {
  return {
      {"--merge", "", "", "glue boundary edges of all parts whose end points coincide (report 3.3)"},
      {"--tolerance", "", "T", "merge distance (default 1e-3 of the bounding box diagonal)"},
      {"--subdiv", "", "N", "Catmull-Clark subdivision levels (default 0)"},
      {"--rule", "", "RULE",
       "smooth-vertex rule: classic (Catmull-Clark, default) or report (the 2016 report's)"},
      {"--boundary", "", "MODE",
       "what subdivision does at a border: edge-only (default: border edges are creases, a vertex of one "
       "face follows them), edge-and-corner (a vertex of one face stays put), none (faces touching the "
       "border "
       "are holes: they shape their neighbours but are not output); OpenSubdiv's modes of the same names"},
      {"--crease-method", "", "METHOD",
       "how semi-sharp crease weights decay: uniform (default: 1 per level) or chaikin (evened out along a "
       "crease); OpenSubdiv's creasing methods, an OBJ's `t creasemethod`"},
      {"--smooth-triangles", "", "",
       "OpenSubdiv's smooth triangle rule: edge points beside a triangle lean towards its centre (an OBJ's "
       "`t smoothtriangles`)"},
      {"--offset", "", "D", "thicken into a closed solid, D on each side of the surface (D > 0)"},
      {"--subdiv-after", "", "M", "Catmull-Clark levels after --offset, to round the rims (default 0)"},
      {"--force", "", "",
       "compute results whose estimated size exceeds the memory budget (4 GB), expand scenes of more than "
       "1000000 instances"},
  };
}

namespace {

void read_merge(const Arguments& args, PipelineSettings& s) {
  s.should_merge = args.has("--merge");
  if (!s.should_merge) {
    if (args.has("--tolerance")) throw UsageError("--tolerance applies with --merge only");
    return;
  }
  s.merge_tolerance = args.double_value("--tolerance", 0.0);
  if (args.has("--tolerance") && !(s.merge_tolerance > 0))
    throw UsageError("--tolerance expects a positive distance, found '" + *args.value("--tolerance") + "'");
}

}  // namespace

PipelineSettings pipeline_settings(const Arguments& args, Stage stage) {
  PipelineSettings s;
  s.stage = stage;
  read_merge(args, s);
  s.subdivision_levels = args.int_value("--subdiv", 0, 0, 12);
  s.subdivision_after = args.int_value("--subdiv-after", 0, 0, 12);
  if (const auto rule = args.value("--rule")) {
    if (*rule == "classic")
      s.rule = SubdivisionRule::classic;
    else if (*rule == "report")
      s.rule = SubdivisionRule::report;
    else
      throw UsageError("--rule expects classic or report, found '" + *rule + "'");
  }
  if (const auto boundary = args.value("--boundary")) {
    const auto mode = parse_boundary_mode(*boundary);
    if (!mode)
      throw UsageError("--boundary expects none, edge-only or edge-and-corner, found '" + *boundary + "'");
    s.boundary = *mode;
  }
  if (const auto method = args.value("--crease-method")) {
    const auto parsed = parse_crease_method(*method);
    if (!parsed) throw UsageError("--crease-method expects uniform or chaikin, found '" + *method + "'");
    s.creases.method = *parsed;
  }
  s.creases.smooth_triangles = args.has("--smooth-triangles");
  if (args.has("--offset")) {
    s.offset_distance = args.double_value("--offset", 0.0);
    if (s.offset_distance <= 0.0)
      throw UsageError("--offset expects a positive distance, found " + *args.value("--offset"));
  }
  if (s.subdivision_after > 0 && !args.has("--offset")) throw UsageError("--subdiv-after needs --offset");
  s.force = args.has("--force");
  s.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  return s;
}

void apply_obj_tags(const ObjSubdivisionTags& tags, const Arguments& args, PipelineSettings& settings) {
  if (tags.boundary && !args.has("--boundary")) settings.boundary = *tags.boundary;
  if (tags.crease_method && !args.has("--crease-method")) settings.creases.method = *tags.crease_method;
  if (tags.smooth_triangles && !args.has("--smooth-triangles"))
    settings.creases.smooth_triangles = *tags.smooth_triangles;
}

void apply_scene_stages(const std::vector<SceneDocument>& scenes, const Arguments& args,
                        PipelineSettings& settings) {
  for (const SceneDocument& document : scenes) {
    const scene::StageSettings stages = document.scene()->stage_settings();
    if (stages.subdivision_levels && !args.has("--subdiv"))
      settings.subdivision_levels = std::max(settings.subdivision_levels, *stages.subdivision_levels);
    if (stages.boundary && !args.has("--boundary")) settings.boundary = *stages.boundary;
    if (stages.offset_distance && !args.has("--offset"))
      settings.offset_distance = std::max(settings.offset_distance, *stages.offset_distance);
  }
  // After the levels are known: the successor's files weld before they subdivide.
  bool is_welding = false;
  for (const SceneDocument& document : scenes)
    is_welding = scene::weld_before_subdividing(document.scene()->stage_settings(), settings) || is_welding;
  if (is_welding && !args.has("--merge")) std::cerr << "nome: note: " << scene::welding_note << "\n";
}

}  // namespace nome::cli
