#include <iostream>

#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/report_format.hpp"
#include "cli/scene_format.hpp"
#include "nome/ops/subdivided_report.hpp"

namespace nome::cli {

int info_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {{"--json", "", "", "print one JSON object instead of text"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("info", "nome info FILE... [--json] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Prints the sliders and instances of each scene, then the topology report (V, E, F, chi,\n"
                 "orientability, borders, genus per part). When the last stage is a subdivision that keeps\n"
                 "every face, the report is counted on the mesh before it (subdivision keeps chi,\n"
                 "orientability, borders and parts; V, E, F follow from the counts) and says so.\n\n"
              << parsed.help();
    return 0;
  }
  LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, {}, false);
  const LastSubdivision last = loaded.pipeline.run_to_last_subdivision(loaded.settings);
  print_warnings(loaded.pipeline.warnings());  // those of a last stage run_input left (an offset)
  const TopologyReport report =
      last.levels > 0 ? subdivided_topology_report(*last.input, last.levels) : topology_report(*last.input);
  const std::vector<scene::Scene>& scenes = loaded.scenes;
  if (parsed.has("--json")) {
    std::string json = report_json(report);
    // The contract's keys stay as they are; the scenes' sliders and instances ride along, and so does the
    // number of subdivision levels the report was derived over.
    json.erase(json.rfind('}'));
    if (last.levels > 0) json += ", \"derived_over_levels\": " + std::to_string(last.levels);
    if (!scenes.empty()) {
      json += ", \"scenes\": [";
      for (size_t i = 0; i < scenes.size(); ++i) json += (i ? ", " : "") + scene_json(scenes[i]);
      json += "]";
    }
    std::cout << json << "}\n";
  } else {
    for (const scene::Scene& s : scenes) std::cout << scene_text(s);
    if (last.levels > 0)
      std::cout << "(counted on the mesh before the last " << last.levels
                << " subdivision levels: they keep chi, orientability, borders and parts)\n";
    std::cout << report_text(report);
  }
  return 0;
}

}  // namespace nome::cli
