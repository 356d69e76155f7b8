#include <iostream>

#include <glm/gtc/matrix_transform.hpp>

#include "cli/check_format.hpp"
#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "cli/print_check_input.hpp"
#include "cli/progress_bar.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/io/three_mf.hpp"
#include "nome/scene/save_nome.hpp"

namespace nome::cli {
namespace {

// Above this many triangles `nome export` skips the print check unless asked (--check).
constexpr std::uint64_t check_limit = 2'000'000;

std::vector<OptionSpec> export_options() {
  std::vector<OptionSpec> specs = {
      {"--output", "-o", "OUT",
       "output file: .obj, .stl, .3mf, or .nome (saves the scene with its slider values)"},
      {"--ascii", "", "", "write ASCII STL instead of binary"},
      {"--unit", "", "mm|cm|in|m", "the length one model unit stands for in a .3mf (default mm)"},
      {"--scale", "", "S", "multiply every position by S (.stl and .3mf)"},
      {"--check", "", "", "run the print check whatever the size (.stl, .3mf)"},
      {"--no-check", "", "", "skip the print check"},
      {"--min-wall", "", "D", "the print check's minimum wall (default: 2 x the offset distance)"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  return specs;
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

}  // namespace

int export_command(const std::vector<std::string>& args) {
  Arguments parsed("export",
                   "nome export FILE... -o OUT.obj|OUT.stl|OUT.3mf [--ascii] [--unit U] [--scale S] "
                   "[--check|--no-check] [pipeline options]",
                   export_options());
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout
        << "Writes the result of the pipeline as OBJ (exact positions), STL (binary by default) or 3MF\n"
           "(one object per part, the scene's colours, a unit). STL and 3MF output is followed by the\n"
           "print check of 'nome check' (a warning when the solid is not printable), up to "
        << check_limit << "\ntriangles unless --check or --no-check says otherwise.\n\n"
        << "Subdivision follows OpenSubdiv's Catmull-Clark: --boundary none|edge-only|edge-and-corner\n"
           "as its boundary interpolation (default edge-only), crease weights with its meaning:\n"
           "`sharp W (a b ...) endsharp` in a scene, OpenSubdiv's `t crease`/`t corner` tags in an OBJ;\n"
           "a weight w keeps an edge a crease for floor(w) levels and blends the rest, 10 or none is\n"
           "infinitely sharp. An OBJ's `t hole`, `t interpolateboundary`, `t creasemethod chaikin` and\n"
           "`t smoothtriangles` apply; an OBJ written without subdivision keeps all of them.\n\n"
        << parsed.help();
    return 0;
  }
  const auto out = parsed.value("--output");
  if (!out) throw UsageError("export needs -o OUT.obj, -o OUT.stl or -o OUT.3mf");
  const std::filesystem::path path(*out);
  const std::string ext = path.extension().string();
  if (ext != ".obj" && ext != ".stl" && ext != ".3mf" && ext != ".nome")
    throw UsageError("output must end in .obj, .stl, .3mf or .nome, found '" + *out + "'");
  if (parsed.has("--ascii") && ext != ".stl") throw UsageError("--ascii applies to .stl output only");
  if (parsed.has("--unit") && ext != ".3mf") throw UsageError("--unit applies to .3mf output only");
  if (parsed.has("--scale") && ext != ".stl" && ext != ".3mf")
    throw UsageError("--scale applies to .stl and .3mf");
  if (parsed.has("--check") && parsed.has("--no-check"))
    throw UsageError("--check and --no-check exclude each other");
  ThreeMfOptions three_mf;
  if (const auto unit = parsed.value("--unit")) {
    const auto parsed_unit = parse_length_unit(*unit);
    if (!parsed_unit) throw UsageError("--unit expects mm, cm, in or m, found '" + *unit + "'");
    three_mf.unit = *parsed_unit;
  }
  three_mf.scale = parsed.double_value("--scale", 1.0);
  if (!(three_mf.scale > 0.0))
    throw UsageError("--scale expects a positive factor, found " + *parsed.value("--scale"));
  ProgressBar bar(parsed.has("--quiet"));
  LoadedInput loaded = run_input(parsed, Stage::subdivided_offset, bar.sink());
  const Mesh& mesh = loaded.pipeline.run(loaded.settings);
  if (ext == ".nome") {
    if (loaded.scenes.size() != 1 || parsed.positionals().size() != 1)
      throw UsageError("-o OUT.nome saves one scene: give exactly one .nome, .nom or .slf file");
    scene::write_nome(loaded.scenes.front(), path);
    std::cerr << "nome: wrote " << *out << " (" << loaded.scenes.front().parameters().size() << " sliders, "
              << loaded.scenes.front().instances().size() << " top-level instances)\n";
    return 0;
  }
  if (ext == ".obj")
    write_obj(path, mesh, loaded.kept_tags);
  else if (ext == ".3mf")
    write_3mf(path, mesh, three_mf);
  else if (three_mf.scale != 1.0)
    write_stl(path, transformed(mesh, glm::scale(glm::dmat4(1.0), Vec3(three_mf.scale))),
              parsed.has("--ascii") ? StlFormat::ascii : StlFormat::binary, bar.sink());
  else
    write_stl(path, mesh, parsed.has("--ascii") ? StlFormat::ascii : StlFormat::binary, bar.sink());
  bar.finish();
  const std::uint64_t triangles = triangle_count(mesh);
  std::cerr << "nome: wrote " << *out << " (" << mesh.num_vertices() << " vertices, " << mesh.num_faces()
            << " faces)\n";
  if (ext != ".obj") report_check(loaded, parsed, triangles);
  return 0;
}

}  // namespace nome::cli
