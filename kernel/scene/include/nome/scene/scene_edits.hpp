#pragma once

#include <string>
#include <vector>

#include "nome/mesh/named_sharp_edge.hpp"

namespace nome::scene {

// The editing model's data as a .nome file holds it (report 7.3.3: `consolidate`, `delete` and
// `sharpedges` blocks): faces the user added, by their vertices' names (the consolidated mesh); deleted
// faces by full hierarchical name; edges marked sharp by full vertex names with their weights.
struct SceneEdits {
  std::vector<std::vector<std::string>> consolidated;
  std::vector<std::string> deleted;
  std::vector<NamedSharpEdge> sharp;

  bool empty() const { return consolidated.empty() && deleted.empty() && sharp.empty(); }
};

}  // namespace nome::scene
