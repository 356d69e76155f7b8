#include <iostream>

#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/report_format.hpp"

namespace nome::cli {

int info_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {{"--json", "", "", "print one JSON object instead of text"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("info", "nome info FILE... [--json] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Prints the topology report (V, E, F, chi, orientability, borders, genus per part).\n\n"
              << parsed.help();
    return 0;
  }
  const Mesh mesh = load_input(parsed);
  const TopologyReport report = topology_report(mesh);
  std::cout << (parsed.has("--json") ? report_json(report) : report_text(report));
  return 0;
}

}  // namespace nome::cli
