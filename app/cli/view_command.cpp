#include <iostream>

#include "cli/arguments.hpp"
#include "cli/commands.hpp"
#include "nome/io/read_scene.hpp"
#include "viewer/commands/script.hpp"
#include "viewer/viewer.hpp"

namespace nome::cli {

int view_command(const std::vector<std::string>& args) {
  Arguments parsed("", "nome [FILE [SAVED.anom ...]] [--script S.txt] [--size WxH] [--quads | --triangles]",
                   {{"--script", "", "S.txt", "replay the viewer commands in S.txt, one a line"},
                    {"--size", "", "WxH", "window size in screen pixels (default 1280x800)"},
                    {"--quads", "", "", "pair a .sif file's triangles into quads (the window's default)"},
                    {"--triangles", "", "", "keep a .sif file's triangles as they are"}});
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout
        << "Opens the viewer window on FILE (.nome .nom .slf .sif .obj .stl); each SAVED.anom after a scene\n"
        << "applies its saved slider values and working mesh to it.\n\n"
        << parsed.help() << "\n"
        << viewer::script_synopsis();
    return 0;
  }
  viewer::ViewerOptions options;
  for (const std::string& file : parsed.positionals()) {
    if (is_anom_file(file)) {
      if (!options.file || !is_scene_file(*options.file))
        throw UsageError(file + ": an .anom file applies to an open scene: give the .nome file before it");
      options.anom_files.emplace_back(file);
    } else if (options.file) {
      throw UsageError("the viewer opens one file at a time (and the .anom files that apply to it)");
    } else {
      options.file = file;
    }
  }
  if (const auto script = parsed.value("--script")) options.script = *script;
  if (parsed.has("--quads") && parsed.has("--triangles"))
    throw UsageError("--quads and --triangles exclude each other");
  options.pair_sif_triangles = !parsed.has("--triangles");
  if (const auto size = parsed.value("--size")) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(size->c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 64 || h < 64 || w > 8192 ||
        h > 8192)
      throw UsageError("--size expects WxH between 64x64 and 8192x8192, found '" + *size + "'");
    options.width = w;
    options.height = h;
    options.has_size = true;
  }
  return viewer::run_viewer(options);
}

}  // namespace nome::cli
