#include <iostream>

#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/report_format.hpp"
#include "cli/scene_format.hpp"

namespace nome::cli {

int info_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {{"--json", "", "", "print one JSON object instead of text"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("info", "nome info FILE... [--json] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Prints the sliders and instances of each scene, then the topology report (V, E, F, chi,\n"
                 "orientability, borders, genus per part).\n\n"
              << parsed.help();
    return 0;
  }
  std::vector<scene::Scene> scenes;
  const Mesh mesh = load_input(parsed, Stage::subdivided_offset, &scenes);
  const TopologyReport report = topology_report(mesh);
  if (parsed.has("--json")) {
    std::string json = report_json(report);
    if (!scenes.empty()) {
      // The contract's keys stay as they are; the scenes' sliders and instances ride along.
      json.erase(json.rfind('}'));
      json += ", \"scenes\": [";
      for (size_t i = 0; i < scenes.size(); ++i) json += (i ? ", " : "") + scene_json(scenes[i]);
      json += "]}\n";
    }
    std::cout << json;
  } else {
    for (const scene::Scene& s : scenes) std::cout << scene_text(s);
    std::cout << report_text(report);
  }
  return 0;
}

}  // namespace nome::cli
