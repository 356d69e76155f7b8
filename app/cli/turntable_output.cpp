#include "cli/turntable_output.hpp"

#include <cmath>
#include <cstdio>

#include "render/gif.hpp"
#include "render/turntable.hpp"

namespace nome::cli {

std::vector<OptionSpec> turntable_options() {
  return {{"--turntable", "", "N",
           "N pictures of the model turning once about the vertical axis: OUT.gif animates them, OUT.png "
           "writes OUT_001.png ... (or one sheet with --sheet)"},
          {"--sheet", "", "", "with --turntable: one contact sheet of the frames (--size is the sheet's)"},
          {"--frame-ms", "", "MS", "with --turntable and OUT.gif: milliseconds per frame (default 80)"}};
}

void check_turntable_arguments(const Arguments& parsed, const std::filesystem::path& out) {
  const bool is_turntable = parsed.has("--turntable");
  if (out.extension() == ".gif" && !is_turntable)
    throw UsageError("an animated .gif is a turntable: give --turntable N (or write a .png)");
  if (!is_turntable && (parsed.has("--sheet") || parsed.has("--frame-ms")))
    throw UsageError("--sheet and --frame-ms go with --turntable N");
  if (is_turntable && parsed.has("--views")) throw UsageError("--turntable and --views exclude each other");
  if (parsed.has("--sheet") && out.extension() != ".png") throw UsageError("--sheet writes a .png");
  if (parsed.has("--frame-ms") && out.extension() != ".gif")
    throw UsageError("--frame-ms applies to .gif output");
}

std::string write_turntable(const Mesh& mesh, render::SnapshotOptions options, const Arguments& parsed,
                            const std::filesystem::path& out) {
  const int count = parsed.int_value("--turntable", 12, 2, 360);
  const bool is_sheet = parsed.has("--sheet");
  if (is_sheet) {
    // Tiles that make up a sheet of about the asked size.
    const int columns = int(std::ceil(std::sqrt(double(count))));
    const int rows = (count + columns - 1) / columns;
    options.width = std::max(16, options.width / columns);
    options.height = std::max(16, options.height / rows);
  }
  const std::vector<render::Image> frames = render::render_turntable(mesh, options, count);
  const std::string size = std::to_string(frames[0].width) + "x" + std::to_string(frames[0].height);
  if (out.extension() == ".gif") {
    render::write_gif(out, frames, parsed.int_value("--frame-ms", 80, 10, 10000));
    return out.string() + " (" + std::to_string(count) + " frames of " + size + ")";
  }
  if (is_sheet) {
    const render::Image sheet = render::contact_sheet(frames);
    render::write_png(out, sheet);
    return out.string() + " (a sheet of " + std::to_string(count) + " frames of " + size + ")";
  }
  for (int i = 0; i < count; ++i) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "_%03d", i + 1);
    std::filesystem::path frame = out;
    frame.replace_filename(out.stem().string() + suffix + ".png");
    render::write_png(frame, frames[std::size_t(i)]);
  }
  return std::to_string(count) + " frames " + out.stem().string() + "_001.png ... (" + size + ")";
}

}  // namespace nome::cli
