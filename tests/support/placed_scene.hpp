#pragma once

#include <string>

namespace nome::test {

// A generator made on line 2 and a mesh whose face statements are on lines 7 and 8, both placed (lines 10
// and 11): the scene whose statements the source-place tests look up.
inline const std::string placed_scene =
    "bank b set n 4 3 8 1 endbank\n"
    "funnel fu ({expr $b_n} 1 0.5 1) endfunnel\n"
    "point a (0 0 3) endpoint\n"
    "point c (1.5 0 3) endpoint\n"
    "point d (1.5 1.5 3) endpoint\n"
    "mesh m\n"
    "  face up (a c d) endface\n"
    "  face down (a d c) endface\n"
    "endmesh\n"
    "instance i1 fu endinstance\n"
    "instance i2 m endinstance\n";

}  // namespace nome::test
