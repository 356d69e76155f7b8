#pragma once

#include <vector>

#include "cli/arguments.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/scene/scene.hpp"

namespace nome::cli {

// What the FILE arguments hold: the scenes (.nome/.nom/.slf, each .anom applied to the scene before it)
// with their --set overrides applied, and the geometry: one part per scene (its top-level instances as
// a disjoint union) and per flat file (.obj, .stl, .sif), each with the file it came from.
struct InputFiles {
  std::vector<scene::Scene> scenes;
  std::vector<PolygonSoup> parts;
  std::vector<std::string> part_files;
};

InputFiles read_input_files(const Arguments& args);

// Appends `part` to `into` as separate vertices and faces, keeping names, colours and sharp edges.
void append_part(PolygonSoup& into, const PolygonSoup& part);

// "BANK_PARAM=VALUE" of --set, applied to every scene that has the parameter.
void apply_overrides(std::vector<scene::Scene>& scenes, const std::vector<std::string>& overrides);

}  // namespace nome::cli
