#include <iostream>

#include "cli/check_format.hpp"
#include "cli/commands.hpp"
#include "cli/print_check_input.hpp"
#include "cli/progress_bar.hpp"

namespace nome::cli {

int check_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {
      {"--min-wall", "", "D", "thinnest wall the printer makes (default: 2 x the offset distance)"},
      {"--json", "", "", "print one JSON object instead of text"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("check", "nome check FILE... [--min-wall D] [--json] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Checks whether the offset solid prints as meant: faces the offset turns inside out\n"
                 "(fold-overs), two sheets of the surface closer than the minimum wall away from where the\n"
                 "surface crosses itself (near misses), and the curves where distant parts of the surface\n"
                 "pass through each other (crossings, where the slab fuses: by design in a Klein bottle).\n"
                 "Printable unless there are fold-overs or near misses. Face ids are those of the surface\n"
                 "before the offset (the subdivided stage).\n\n"
                 "Exit status: 0 printable, 3 not printable, 1 an error in the input, 2 a usage error.\n\n"
              << parsed.help();
    return 0;
  }
  const double min_wall = parsed.double_value("--min-wall", 0.0);
  if (parsed.has("--min-wall") && !(min_wall > 0.0))
    throw UsageError("--min-wall expects a positive distance, found " + *parsed.value("--min-wall"));
  ProgressBar bar(parsed.has("--quiet"));
  LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, bar.sink());
  if (loaded.settings.distance() == 0.0 && !parsed.has("--min-wall"))
    std::cerr << "nome: note: no --offset and no --min-wall: only crossings are looked for\n";
  const PrintCheck check = check_loaded_input(loaded, min_wall, bar.sink());
  bar.finish();
  std::cout << (parsed.has("--json") ? check_json(check) : check_text(check));
  return check.is_printable() ? 0 : 3;
}

}  // namespace nome::cli
