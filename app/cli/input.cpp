#include "cli/input.hpp"

#include "cli/merge_option.hpp"
#include "nome/error.hpp"
#include "nome/io/read_polygons.hpp"

namespace nome::cli {
namespace {

void append(PolygonSoup& into, const PolygonSoup& part) {
  const Index base = into.num_vertices();
  const bool names = !into.vertex_names.empty() || !part.vertex_names.empty();
  if (names) into.vertex_names.resize(into.positions.size());
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  if (names) {
    into.vertex_names.insert(into.vertex_names.end(), part.vertex_names.begin(), part.vertex_names.end());
    into.vertex_names.resize(into.positions.size());
  }
  for (Index f = 0; f < part.num_faces(); ++f) {
    for (Index c = part.face_offsets[f]; c < part.face_offsets[f + 1]; ++c)
      into.face_vertices.push_back(part.face_vertices[c] + base);
    into.face_offsets.push_back(Index(into.face_vertices.size()));
  }
  for (auto [a, b] : part.sharp_edges) into.sharp_edges.emplace_back(a + base, b + base);
}

// build_mesh on all files together; a topology error names the file at fault, with element numbers of
// that file alone: the parts are rebuilt one by one (only on this error path) to find it.
Mesh build_naming_the_file(PolygonSoup soup, std::vector<PolygonSoup>& parts,
                           const std::vector<std::string>& files) {
  try {
    return build_mesh(std::move(soup));
  } catch (const TopologyError&) {
    for (size_t i = 0; i < parts.size(); ++i) {
      try {
        build_mesh(std::move(parts[i]));
      } catch (const TopologyError& in_part) {
        throw TopologyError(files[i] + ": " + in_part.what());
      }
    }
    throw;
  }
}

}  // namespace

std::vector<OptionSpec> input_options() {
  return merge_options();
}

Mesh load_input(const Arguments& args) {
  return load_input(args, Stage::offset);
}

Stage parse_stage(const std::string& name) {
  if (name == "scene") return Stage::scene;
  if (name == "merged") return Stage::merged;
  const std::pair<const char*, const char*> pending[] = {{"subdivided", "subdivision"},
                                                         {"offset", "offsetting"}};
  for (const auto& [stage, feature] : pending)
    if (name == stage)
      throw UsageError("--stage " + name + ": " + feature + " is not built yet (available: scene, merged)");
  throw UsageError("--stage expects scene, merged, subdivided or offset, found '" + name + "'");
}

Mesh load_input(const Arguments& args, Stage last) {
  if (args.positionals().empty()) throw UsageError("no input FILE given");
  PolygonSoup soup;
  std::vector<PolygonSoup> parts;
  for (const std::string& file : args.positionals()) {
    parts.push_back(read_polygons(file));
    append(soup, parts.back());
  }
  Mesh mesh = build_naming_the_file(std::move(soup), parts, args.positionals());
  if (last == Stage::scene) return mesh;
  return apply_merge_option(std::move(mesh), args);
}

}  // namespace nome::cli
