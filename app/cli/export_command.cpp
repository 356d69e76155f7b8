#include <iostream>
#include <optional>

#include "cli/check_format.hpp"
#include "cli/commands.hpp"
#include "cli/export_result.hpp"
#include "cli/input.hpp"
#include "cli/print_check_input.hpp"
#include "cli/print_setup_arguments.hpp"
#include "cli/progress_bar.hpp"

namespace nome::cli {
namespace {

// Above this many triangles `nome export` skips the print check unless asked (--check).
constexpr std::uint64_t check_limit = 2'000'000;

std::vector<OptionSpec> export_options() {
  std::vector<OptionSpec> specs = {
      {"--output", "-o", "OUT",
       "output file: .obj, .stl, .3mf, .glb (glTF with colours), .ply (vertex colours), or .nome (saves the "
       "scene with its slider values)"},
      {"--ascii", "", "", "write ASCII STL instead of binary"},
      {"--unit", "", "mm|cm|in|m", "the length one model unit stands for in a .3mf (default mm)"},
      {"--scale", "", "S", "multiply every position by S (.stl and .3mf)"},
      {"--check", "", "", "run the print check whatever the size (.stl, .3mf)"},
      {"--no-check", "", "", "skip the print check"},
      {"--min-wall", "", "D", "the print check's minimum wall (default: 2 x the offset distance)"}};
  for (OptionSpec& s : print_setup_options()) specs.push_back(std::move(s));
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  return specs;
}

// The scene's kept print preparation: that of the one scene read, if any.
std::optional<PrintPlacementOptions> kept_print_setup(const LoadedInput& loaded) {
  if (loaded.scenes.size() != 1) return std::nullopt;
  return loaded.scenes.front().scene()->print_setup();
}

// `-o OUT.nome`: the scene with its slider values and the print preparation asked for.
void save_scene(LoadedInput& loaded, const Arguments& parsed, const std::filesystem::path& path) {
  if (loaded.scenes.size() != 1 || parsed.positionals().size() != 1)
    throw UsageError("-o OUT.nome saves one scene: give exactly one .nome, .nom or .slf file");
  SceneDocument& document = loaded.scenes.front();
  const PrintPlacementOptions setup =
      print_setup_argument(parsed, document.scene()->print_setup(), LengthUnit::millimeter);
  if (!setup.is_identity()) document.set_print_setup(setup);
  document.save_all(path);
  const scene::Scene& scene = *document.scene();
  std::cerr << "nome: wrote " << path.string() << " (" << scene.parameters().size() << " sliders, "
            << scene.instances().size() << " top-level instances)\n";
}

// The print check after writing a solid for a printer: a line for every outcome, never silence.
void report_check(LoadedInput& loaded, const Arguments& parsed, std::uint64_t triangles) {
  if (parsed.has("--no-check")) return;
  if (triangles > check_limit && !parsed.has("--check")) {
    std::cerr << "nome: print check skipped: " << triangles << " triangles (over " << check_limit
              << "); run 'nome check' with the same files and options, or export with --check\n";
    return;
  }
  ProgressBar bar(parsed.has("--quiet"));
  const PrintCheck check = check_loaded_input(loaded, parsed.double_value("--min-wall", 0.0), bar.sink());
  bar.finish();
  std::cerr << "nome: " << (check.is_printable() ? "" : "warning: ")
            << "print check: " << check_summary(check)
            << (check.is_printable() ? "\n" : "; 'nome check' lists the places\n");
}

// The output format's options, checked against each other and the output's kind.
ExportFormat export_format(const Arguments& parsed, const std::string& ext) {
  if (parsed.has("--ascii") && ext != ".stl") throw UsageError("--ascii applies to .stl output only");
  if (parsed.has("--unit") && ext != ".3mf") throw UsageError("--unit applies to .3mf output only");
  if (parsed.has("--scale") && ext != ".stl" && ext != ".3mf")
    throw UsageError("--scale applies to .stl and .3mf");
  if (parsed.has("--check") && parsed.has("--no-check"))
    throw UsageError("--check and --no-check exclude each other");
  ExportFormat format;
  format.stl = parsed.has("--ascii") ? StlFormat::ascii : StlFormat::binary;
  ThreeMfOptions& three_mf = format.three_mf;
  if (const auto unit = parsed.value("--unit")) {
    const auto parsed_unit = parse_length_unit(*unit);
    if (!parsed_unit) throw UsageError("--unit expects mm, cm, in or m, found '" + *unit + "'");
    three_mf.unit = *parsed_unit;
  }
  three_mf.scale = parsed.double_value("--scale", 1.0);
  if (!(three_mf.scale > 0.0))
    throw UsageError("--scale expects a positive factor, found " + *parsed.value("--scale"));
  return format;
}

}  // namespace

int export_command(const std::vector<std::string>& args) {
  Arguments parsed(
      "export",
      "nome export FILE... -o OUT.obj|.stl|.3mf|.glb|.ply|.nome [--ascii] [--unit U] [--scale S] "
      "[--check|--no-check] [pipeline options]",
      export_options());
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout
        << "Writes the result of the pipeline as OBJ (exact positions), STL (binary by default), 3MF\n"
           "(one object per part, the scene's colours, a unit), binary glTF (.glb: a material per colour,\n"
           "smooth normals) or PLY (polygons, vertex colours). STL and 3MF output is followed by the\n"
           "print check of 'nome check' (a warning when the solid is not printable), up to "
        << check_limit << "\ntriangles unless --check or --no-check says otherwise.\n\n"
        << "Subdivision follows OpenSubdiv's Catmull-Clark: --boundary none|edge-only|edge-and-corner\n"
           "as its boundary interpolation (default edge-only), crease weights with its meaning:\n"
           "`sharp W (a b ...) endsharp` in a scene (a generator's rim: `sharp W border (v) endsharp`),\n"
           "OpenSubdiv's `t crease`/`t corner` tags in an OBJ;\n"
           "a weight w keeps an edge a crease for floor(w) levels and blends the rest, 10 or none is\n"
           "infinitely sharp. An OBJ's `t hole`, `t interpolateboundary`, `t creasemethod chaikin` and\n"
           "`t smoothtriangles` apply (--boundary, --crease-method and --smooth-triangles win); an OBJ\n"
           "written without subdivision keeps all of them.\n\n"
           "Print preparation (--fit-height, --fit-size, --rest-on; a scene's `printsetup` statement\n"
           "keeps them, and -o OUT.nome writes the options into it) scales the solid and stands it on a\n"
           "face, its lowest point at z = 0, before writing.\n\n"
        << parsed.help();
    return 0;
  }
  const auto out = parsed.value("--output");
  if (!out) throw UsageError("export needs -o OUT.obj, .stl, .3mf, .glb, .ply or .nome");
  const std::filesystem::path path(*out);
  const std::string ext = path.extension().string();
  if (ext != ".obj" && ext != ".stl" && ext != ".3mf" && ext != ".glb" && ext != ".ply" && ext != ".nome")
    throw UsageError("output must end in .obj, .stl, .3mf, .glb, .ply or .nome, found '" + *out + "'");
  ExportFormat format = export_format(parsed, ext);
  ProgressBar bar(parsed.has("--quiet"));
  if (ext == ".nome") {
    LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, bar.sink());
    save_scene(loaded, parsed, path);
    return 0;
  }
  // The last subdivision level is left to write_result: it may go from its quads straight to the file.
  LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, bar.sink(), false);
  format.placement = print_setup_argument(parsed, kept_print_setup(loaded), format.three_mf.unit);
  if (!format.placement.is_identity() && parsed.has("--scale"))
    throw UsageError(
        "--scale and print preparation (--fit-height, --fit-size, --rest-on, a printsetup) "
        "exclude each other");
  const ExportCounts counts = write_result(loaded, path, format, bar.sink());
  bar.finish();
  std::cerr << "nome: wrote " << *out << " (" << counts.vertices << " vertices, " << counts.faces
            << " faces)\n";
  if (ext == ".stl" || ext == ".3mf") report_check(loaded, parsed, counts.triangles);
  return 0;
}

}  // namespace nome::cli
