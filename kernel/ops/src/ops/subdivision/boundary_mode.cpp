#include "nome/ops/boundary_mode.hpp"

#include <algorithm>
#include <string>

namespace nome {

const char* to_string(BoundaryMode mode) {
  switch (mode) {
    case BoundaryMode::none:
      return "none";
    case BoundaryMode::edge_only:
      return "edge-only";
    case BoundaryMode::edge_and_corner:
      return "edge-and-corner";
  }
  return "?";
}

std::optional<BoundaryMode> parse_boundary_mode(std::string_view word) {
  for (BoundaryMode mode : {BoundaryMode::none, BoundaryMode::edge_only, BoundaryMode::edge_and_corner}) {
    std::string name = to_string(mode);
    if (word == name) return mode;
    std::replace(name.begin(), name.end(), '-', '_');
    if (word == name) return mode;
  }
  return std::nullopt;
}

}  // namespace nome
