#include <iostream>

#include "cli/commands.hpp"
#include "cli/input.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/scene/save_nome.hpp"

namespace nome::cli {

int export_command(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = {
      {"--output", "-o", "OUT", "output file: .obj, .stl, or .nome (saves the scene with its slider values)"},
      {"--ascii", "", "", "write ASCII STL instead of binary"}};
  for (OptionSpec& s : input_options()) specs.push_back(std::move(s));
  Arguments parsed("export", "nome export FILE... -o OUT.obj|OUT.stl [--ascii] [pipeline options]", specs);
  parsed.parse(args);
  if (parsed.has("--help")) {
    std::cout
        << "Writes the result of the pipeline as OBJ (exact positions) or STL (binary by default).\n\n"
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
  if (!out) throw UsageError("export needs -o OUT.obj or -o OUT.stl");
  const std::filesystem::path path(*out);
  const std::string ext = path.extension().string();
  if (ext != ".obj" && ext != ".stl" && ext != ".nome")
    throw UsageError("output must end in .obj, .stl or .nome, found '" + *out + "'");
  if (parsed.has("--ascii") && ext != ".stl") throw UsageError("--ascii applies to .stl output only");
  std::vector<scene::Scene> scenes;
  ObjSubdivisionTags tags;
  const Mesh mesh = load_input(parsed, Stage::subdivided_offset, &scenes, &tags);
  if (ext == ".nome") {
    if (scenes.size() != 1 || parsed.positionals().size() != 1)
      throw UsageError("-o OUT.nome saves one scene: give exactly one .nome, .nom or .slf file");
    scene::write_nome(scenes.front(), path);
    std::cerr << "nome: wrote " << *out << " (" << scenes.front().parameters().size() << " sliders, "
              << scenes.front().instances().size() << " top-level instances)\n";
    return 0;
  }
  if (ext == ".obj")
    write_obj(path, mesh, tags);
  else
    write_stl(path, mesh, parsed.has("--ascii") ? StlFormat::ascii : StlFormat::binary);
  std::cerr << "nome: wrote " << *out << " (" << mesh.num_vertices() << " vertices, " << mesh.num_faces()
            << " faces)\n";
  return 0;
}

}  // namespace nome::cli
