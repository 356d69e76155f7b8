#include <iostream>

#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/report_format.hpp"
#include "cli/scene_format.hpp"
#include "nome/ops/offset_report.hpp"
#include "nome/ops/subdivided_report.hpp"

namespace nome::cli {
namespace {

// The report of the pipeline's result, counted on the mesh before its last stage where that stage's
// topology follows from it (a subdivision that outputs every face, an offset), and what it was derived
// over, for the output to say.
struct InfoReport {
  TopologyReport report;
  int derived_over_levels = 0;
  bool derived_over_offset = false;
};

// Prints the warnings of the stages run_input left to it.
InfoReport info_report(LoadedInput& loaded) {
  Pipeline& pipeline = loaded.pipeline;
  if (const Mesh* under = pipeline.run_to_last_offset(loaded.settings)) {
    pipeline.offset_normals(*under, loaded.settings.threads);  // warns where the offset is undefined
    print_warnings(pipeline.warnings());
    return {offset_topology_report(*under), 0, true};
  }
  const LastSubdivision last = pipeline.run_to_last_subdivision(loaded.settings);
  print_warnings(pipeline.warnings());
  if (last.levels > 0) return {subdivided_topology_report(*last.input, last.levels), last.levels, false};
  return {topology_report(*last.input), 0, false};
}

}  // namespace

int info_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {{"--json", "", "", "print one JSON object instead of text"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("info", "nome info FILE... [--json] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Prints the sliders and instances of each scene, then the topology report (V, E, F, chi,\n"
                 "orientability, borders, genus per part). When the last stage is a subdivision that keeps\n"
                 "every face, the report is counted on the mesh before it (subdivision keeps chi,\n"
                 "orientability, borders and parts; V, E, F follow from the counts) and says so; so it is\n"
                 "when the last stage is an offset (the solid's topology follows from the surface's).\n\n"
              << parsed.help();
    return 0;
  }
  LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, {}, false);
  const InfoReport info = info_report(loaded);
  const TopologyReport& report = info.report;
  const std::vector<SceneDocument>& scenes = loaded.scenes;
  if (parsed.has("--json")) {
    std::string json = report_json(report);
    // The contract's keys stay as they are; the scenes' sliders and instances ride along, and so does the
    // number of subdivision levels the report was derived over.
    json.erase(json.rfind('}'));
    if (info.derived_over_levels > 0)
      json += ", \"derived_over_levels\": " + std::to_string(info.derived_over_levels);
    if (info.derived_over_offset) json += ", \"derived_over_offset\": true";
    if (!scenes.empty()) {
      json += ", \"scenes\": [";
      for (size_t i = 0; i < scenes.size(); ++i) json += (i ? ", " : "") + scene_json(scenes[i]);
      json += "]";
    }
    std::cout << json << "}\n";
  } else {
    for (const SceneDocument& document : scenes) std::cout << scene_text(document);
    if (info.derived_over_levels > 0)
      std::cout << "(counted on the mesh before the last " << info.derived_over_levels
                << " subdivision levels: they keep chi, orientability, borders and parts)\n";
    if (info.derived_over_offset)
      std::cout << "(counted on the surface under the offset: the solid has twice its chi, no border, and "
                   "two parts for each closed orientable part)\n";
    std::cout << report_text(report);
  }
  return 0;
}

}  // namespace nome::cli
