#include <iostream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "viewer/script.hpp"
#include "viewer/viewer.hpp"

namespace nome::cli {

int view_command(const std::vector<std::string>& args) {
  Arguments parsed("", "nome [FILE] [--script S.txt] [--size WxH]",
                   {{"--script", "", "S.txt", "replay the viewer commands in S.txt, one a line"},
                    {"--size", "", "WxH", "window size in screen pixels (default 1280x800)"}});
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout << "Opens the viewer window on FILE (.nome .anom .sif .slf .obj .stl).\n\n"
              << parsed.help() << "\n"
              << viewer::script_synopsis();
    return 0;
  }
  if (parsed.positionals().size() > 1) throw UsageError("the viewer opens one file at a time");
  viewer::ViewerOptions options;
  if (!parsed.positionals().empty()) options.file = parsed.positionals()[0];
  if (const auto script = parsed.value("--script")) options.script = *script;
  if (const auto size = parsed.value("--size")) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(size->c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 64 || h < 64 || w > 8192 ||
        h > 8192)
      throw UsageError("--size expects WxH between 64x64 and 8192x8192, found '" + *size + "'");
    options.width = w;
    options.height = h;
  }
  return viewer::run_viewer(options);
}

}  // namespace nome::cli
