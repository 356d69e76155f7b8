#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/color_argument.hpp"
#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/print_check_input.hpp"
#include "cli/progress_bar.hpp"
#include "cli/turntable_output.hpp"
#include "nome/error.hpp"
#include "nome/scene/scene_rim_lines.hpp"
#include "render/offscreen_context.hpp"
#include "render/scene_camera.hpp"
#include "render/section_plane.hpp"
#include "render/snapshot.hpp"

namespace nome::cli {
namespace {

// "AxB" with A and B in 1..max, as --size and friends write pairs.
std::pair<double, double> parse_pair(const std::string& option, const std::string& text, char separator,
                                     const char* expected) {
  std::istringstream in(text);
  double a = 0, b = 0;
  char sep = 0;
  if (!(in >> a >> sep >> b) || sep != separator || !(in >> std::ws).eof() || !std::isfinite(a) ||
      !std::isfinite(b))
    throw UsageError(option + " expects " + expected + ", found '" + text + "'");
  return {a, b};
}

// The scenes' render statements where the command line says nothing: the first scene that has one wins.
void apply_render_defaults(const std::vector<SceneDocument>& scenes, const Arguments& args,
                           render::DisplaySettings& display) {
  for (auto it = scenes.rbegin(); it != scenes.rend(); ++it) {
    const scene::RenderDefaults d = it->scene()->render_defaults();
    if (d.background && !args.has("--background")) display.background = glm::vec4(*d.background, 1.0f);
    if (d.front_color && !args.has("--color")) display.front_color = *d.front_color;
    if (d.back_color && !args.has("--backface-color")) {
      display.back_faces = render::BackFacePolicy::different;
      display.back_color = *d.back_color;
    }
    if (!d.lights.empty() && !args.has("--viewer-lights")) display.lights = render::scene_lights(d.lights);
  }
}

render::SnapshotOptions snapshot_options(const Arguments& args) {
  render::SnapshotOptions options;
  if (const auto size = args.value("--size")) {
    const auto [w, h] = parse_pair("--size", *size, 'x', "WIDTHxHEIGHT (e.g. 1024x768)");
    if (w != std::floor(w) || h != std::floor(h) || w < 16 || h < 16 || w > 8192 || h > 8192)
      throw UsageError("--size must be whole numbers of pixels between 16 and 8192, found '" + *size + "'");
    options.width = int(w);
    options.height = int(h);
  }
  render::ViewAngle view;
  if (const auto text = args.value("--view")) {
    const auto [az, el] = parse_pair("--view", *text, ',', "AZ,EL in degrees (e.g. 30,25)");
    if (el < -90 || el > 90)
      throw UsageError("--view elevation must be between -90 and 90, found '" + *text + "'");
    view = {az, el};
  }
  if (const auto text = args.value("--target")) {
    std::istringstream in(*text);
    glm::dvec3 t;
    char c1 = 0, c2 = 0;
    if (!(in >> t.x >> c1 >> t.y >> c2 >> t.z) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof())
      throw UsageError("--target expects X,Y,Z, found '" + *text + "'");
    options.target = t;
  }
  if (args.has("--distance")) {
    const double d = args.double_value("--distance", 0.0);
    if (!(d > 0.0))
      throw UsageError("--distance must be positive, found '" + *args.value("--distance") + "'");
    options.distance = d;
  }
  if (args.has("--fit") && (options.target || options.distance))
    throw UsageError("--fit frames the whole scene: it cannot be combined with --target or --distance");
  options.views = render::views_around(view, args.int_value("--views", 1, 1, 16));
  render::DisplaySettings& display = options.display;
  display.draws_wireframe = args.has("--wire");
  if (args.has("--flat") && args.has("--smooth")) throw UsageError("--flat and --smooth exclude each other");
  display.shading = args.has("--flat")     ? render::Shading::flat
                    : args.has("--smooth") ? render::Shading::smooth
                                           : render::Shading::automatic;
  if (const auto palette = args.value("--palette")) {
    if (*palette == "jipcad")
      render::use_jipcad_palette(display);
    else if (*palette != "nome")
      throw UsageError("--palette expects nome or jipcad, found '" + *palette + "'");
  }
  display.draws_mobius_edges = args.has("--mobius-edges");
  display.draws_borders = args.has("--borders");
  if (const auto back = args.value("--backface-color")) {
    if (*back == "same")
      display.back_faces = render::BackFacePolicy::same;
    else if (*back == "cull")
      display.back_faces = render::BackFacePolicy::cull;
    else
      display.back_color = parse_color("--backface-color", *back);
  }
  if (const auto color = args.value("--color")) display.front_color = parse_color("--color", *color);
  if (const auto background = args.value("--background"))
    display.background = glm::vec4(parse_color("--background", *background), 1.0f);
  options.is_transparent = args.has("--transparent");
  return options;
}

std::vector<OptionSpec> render_options() {
  std::vector<OptionSpec> specs = {
      {"--output", "-o", "OUT", "the PNG to write"},
      {"--size", "", "WxH", "picture size in pixels (default 1024x768)"},
      {"--view", "", "AZ,EL", "azimuth about +Y and elevation in degrees (default 30,25: three-quarter)"},
      {"--views", "", "N", "a contact sheet of N views around the object (azimuths 360/N apart)"},
      {"--fit", "", "", "frame the whole scene in each view (the default)"},
      {"--target", "", "X,Y,Z", "look at this point instead of the scene's centre"},
      {"--distance", "", "D", "eye distance from the target instead of the fitted one"},
      {"--stage", "", "STAGE",
       "show the pipeline up to scene|merged|subdivided|offset|subdivided-offset (default: all of it)"},
      {"--wire", "", "", "draw the real polygon edges over the faces"},
      {"--flat", "", "", "flat shading (one normal per face); by default only unsubdivided results are flat"},
      {"--smooth", "", "", "smooth shading (vertex normals) also where nothing was subdivided"},
      {"--mobius-edges", "", "", "highlight the Möbius edges (where the faces' orientations disagree)"},
      {"--borders", "", "", "highlight the border edges"},
      {"--print-check", "", "",
       "draw the surface before the offset marked by the print check: crossings red, fold-overs magenta, "
       "thin places orange"},
      {"--palette", "", "NAME",
       "default colours: nome (gold and blue) or jipcad (JIPCAD's orange and dark grey)"},
      {"--viewer-lights", "", "", "light with the viewer's own lights even where the file places lights"},
      {"--color", "", "COLOR", "front face colour (#rrggbb, R,G,B in 0..1, or a name)"},
      {"--backface-color", "", "COLOR", "back face colour; 'same' as the front, 'cull' to hide back faces"},
      {"--background", "", "COLOR", "background colour (default white)"},
      {"--transparent", "", "", "transparent background (PNG alpha)"},
      {"--section", "", "x|y|z[=AT]",
       "cut away what lies beyond the plane axis = AT (default: the middle); a solid's cut is filled red"},
      {"--backend", "", "egl|egl-device|osmesa",
       "force the offscreen GL backend (default: EGL surfaceless, else an EGL device, else OSMesa)"},
      {"--verbose", "-v", "", "print the GL backend, vendor, renderer and timings"},
      {"--time", "", "T", "the scenes' $time (default 0)"}};
  for (OptionSpec& s : turntable_options()) specs.push_back(std::move(s));
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  return specs;
}

// --section x|y|z[=AT]: the plane, and the fill when the picture is of a solid (an offset stage).
void apply_section_argument(const Arguments& parsed, const Mesh& mesh, const PipelineSettings& settings,
                            render::DisplaySettings& display) {
  const auto text = parsed.value("--section");
  if (!text) return;
  const std::size_t equals = text->find('=');
  const auto axis = render::parse_section_axis(text->substr(0, equals));
  double at = 0.0;
  if (axis && equals != std::string::npos) {
    std::istringstream in(text->substr(equals + 1));
    if (!(in >> at) || !(in >> std::ws).eof() || !std::isfinite(at))
      throw UsageError("--section expects x, y or z with an optional =AT (z=0.5), found '" + *text + "'");
  } else if (axis) {
    at = render::section_centre(mesh, *axis);
  }
  if (!axis)
    throw UsageError("--section expects x, y or z with an optional =AT (z=0.5), found '" + *text + "'");
  display.section_plane = render::section_plane(*axis, at);
  display.fills_section = settings.distance() > 0.0 && !parsed.has("--print-check");
}

// -o OUT.png, or OUT.gif for a turntable.
std::string output_argument(const Arguments& parsed) {
  const auto out = parsed.value("--output");
  if (!out) throw UsageError("render needs -o OUT.png");
  const auto extension = std::filesystem::path(*out).extension();
  if (extension != ".png" && extension != ".gif")
    throw UsageError("output must end in .png (or .gif with --turntable), found '" + *out + "'");
  check_turntable_arguments(parsed, *out);
  return *out;
}

// ", N polyline segments" when the scenes have polylines (a scene of lines alone has no faces).
std::string polylines_drawn(const render::LineSegments& rims) {
  return rims.empty() ? "" : ", " + std::to_string(rims.segments.size() / 2) + " polyline segments";
}

render::Backend backend_argument(const Arguments& parsed) {
  const auto name = parsed.value("--backend");
  if (!name) return render::Backend::automatic;
  try {
    return render::parse_backend(*name);
  } catch (const InvalidInputError& e) {
    throw UsageError(std::string("--backend: ") + e.what());
  }
}

int print_help(const Arguments& parsed) {
  std::cout
      << "Draws the result headless (no display, no GPU needed) with the viewer's renderer and writes a "
         "PNG.\nFront faces and back faces have their own colours: a one-sided surface shows both. A "
         "scene's polylines are drawn over the faces in the viewer's rim colour.\n\n"
      << parsed.help();
  return 0;
}

}  // namespace

int render_command(const std::vector<std::string>& args) {
  Arguments parsed(
      "render",
      "nome render FILE... -o OUT.png|OUT.gif [--size WxH] [--view AZ,EL] [--turntable N] [--wire] [--flat] "
      "[--backend egl|egl-device|osmesa] [pipeline options]",
      render_options());
  parsed.parse(args);
  if (parsed.has("--help")) return print_help(parsed);
  const std::string out = output_argument(parsed);
  render::SnapshotOptions options = snapshot_options(parsed);
  const render::Backend backend = backend_argument(parsed);
  const Stage stage =
      parsed.has("--stage") ? stage_argument(*parsed.value("--stage")) : Stage::subdivided_offset;
  const bool verbose = parsed.has("--verbose");

  using Clock = std::chrono::steady_clock;
  auto milliseconds = [](Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
  };
  const auto start = Clock::now();
  ProgressBar bar(parsed.has("--quiet"));
  LoadedInput loaded = run_input(parsed, stage, bar.sink());
  const Mesh mesh = parsed.has("--print-check")
                        ? marked_surface(loaded, check_loaded_input(loaded, 0.0, bar.sink()))
                        : loaded.pipeline.take_result();
  bar.finish();
  apply_render_defaults(loaded.scenes, parsed, options.display);
  for (auto it = loaded.scenes.rbegin(); it != loaded.scenes.rend(); ++it)
    options.lens = render::scene_lens(it->scene()->render_defaults(), options.lens);
  options.display.shading = render::shown_shading(options.display.shading, loaded.settings.is_smoothing());
  for (const SceneDocument& document : loaded.scenes)
    render::add_rim_segments(scene::scene_rim_lines(*document.scene()), options.rims);
  apply_section_argument(parsed, mesh, loaded.settings, options.display);
  const double load_ms = milliseconds(start);
  const auto context_start = Clock::now();
  const render::OffscreenContext context(backend);
  const double context_ms = milliseconds(context_start);
  if (verbose) std::cerr << "nome: " << context.platform() << ": " << context.description() << "\n";
  if (parsed.has("--turntable")) {
    std::cerr << "nome: wrote " << write_turntable(mesh, options, parsed, out) << ", " << mesh.num_faces()
              << " faces" << polylines_drawn(options.rims) << ", " << context.platform() << "\n";
    return 0;
  }
  const auto draw_start = Clock::now();
  const render::Image image = render::render_snapshot(mesh, options);
  const double draw_ms = milliseconds(draw_start);
  const auto write_start = Clock::now();
  render::write_png(out, image);
  if (verbose) {
    char figures[160];
    std::snprintf(figures, sizeof figures,
                  "nome: load %.1f ms, context %.1f ms, draw + read-back %.1f ms, PNG %.1f ms\n", load_ms,
                  context_ms, draw_ms, milliseconds(write_start));
    std::cerr << figures;
  }
  std::cerr << "nome: wrote " << out << " (" << image.width << "x" << image.height << ", " << mesh.num_faces()
            << " faces" << polylines_drawn(options.rims) << ", " << context.platform() << ")\n";
  return 0;
}

}  // namespace nome::cli
