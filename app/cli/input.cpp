#include "cli/input.hpp"

#include "cli/merge_option.hpp"
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

}  // namespace

std::vector<OptionSpec> input_options() {
  return merge_options();
}

Mesh load_input(const Arguments& args) {
  if (args.positionals().empty()) throw UsageError("no input FILE given");
  PolygonSoup soup;
  for (const std::string& file : args.positionals()) append(soup, read_polygons(file));
  return apply_merge_option(build_mesh(std::move(soup)), args);
}

}  // namespace nome::cli
