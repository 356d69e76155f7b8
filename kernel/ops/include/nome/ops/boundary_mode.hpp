#pragma once

#include <optional>
#include <string_view>

namespace nome {

// What happens at a border (OpenSubdiv's Sdc::Options::VtxBoundaryInterpolation, same meanings).
enum class BoundaryMode {
  none,       // every base face with a border vertex is a hole: refined, shaping its neighbours, not output
  edge_only,  // border edges are creases; a vertex of a single face follows its border (the default)
  edge_and_corner,  // the same, but a vertex of a single face (two border edges) is a corner: it stays put
};

// "none", "edge-only", "edge-and-corner" (the command line's spelling; the scene language's has '_').
const char* to_string(BoundaryMode mode);
// Either spelling; nothing for any other word.
std::optional<BoundaryMode> parse_boundary_mode(std::string_view word);

}  // namespace nome
