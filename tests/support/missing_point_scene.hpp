#pragma once

#include <string_view>

namespace nome::test {

// A triangle mesh whose second face names a point `x` that no statement defines (at 4:16): JIPCAD skips
// such a point, this program leaves the face out with a warning in JIPCAD's dialect.
inline constexpr std::string_view missing_point_scene =
    "mesh m\n"
    "  point a (0 0 0) endpoint  point b (1 0 0) endpoint  point c (0 1 0) endpoint\n"
    "  face f1 (a b c) endface\n"
    "  face f2 (a c x) endface\n"
    "endmesh\n"
    "instance i m endinstance\n";

}  // namespace nome::test
