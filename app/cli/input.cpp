#include "cli/input.hpp"

#include "cli/merge_option.hpp"
#include "cli/pipeline_options.hpp"
#include "cli/scene_input.hpp"
#include "nome/error.hpp"

namespace nome::cli {
namespace {

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
  std::vector<OptionSpec> options = {
      {"--set", "", "BANK_PARAM=VALUE", "override a slider of a scene (repeatable)", true},
      {"--quads", "", "", "pair the triangles of .sif files into quads where convex and nearly planar"}};
  for (OptionSpec& o : merge_options()) options.push_back(std::move(o));
  for (OptionSpec& o : pipeline_option_specs()) options.push_back(std::move(o));
  return options;
}

Mesh load_input(const Arguments& args) {
  return load_input(args, Stage::offset);
}

Stage parse_stage(const std::string& name) {
  if (name == "scene") return Stage::scene;
  if (name == "merged") return Stage::merged;
  if (name == "subdivided") return Stage::subdivided;
  if (name == "offset") return Stage::offset;
  throw UsageError("--stage expects scene, merged, subdivided or offset, found '" + name + "'");
}

Mesh load_input(const Arguments& args, Stage last) {
  return load_input(args, last, nullptr);
}

Mesh load_input(const Arguments& args, Stage last, std::vector<scene::Scene>* scenes) {
  if (args.positionals().empty()) throw UsageError("no input FILE given");
  InputFiles input = read_input_files(args);
  PolygonSoup soup;
  for (const PolygonSoup& part : input.parts) append_part(soup, part);
  Mesh mesh = build_naming_the_file(std::move(soup), input.parts, input.part_files);
  if (scenes) *scenes = std::move(input.scenes);
  if (last == Stage::scene) return mesh;
  mesh = apply_merge_option(std::move(mesh), args);
  if (last == Stage::merged) return mesh;
  return run_pipeline(mesh, args, last == Stage::offset);
}

}  // namespace nome::cli
