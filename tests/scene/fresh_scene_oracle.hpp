#pragma once

#include <string>

#include "nome/edit/scene_document.hpp"

namespace nome::test {

// A sweep `sw` of an asymmetric triangle along a bent three-point path, capped: a generator that tells
// its positions alone, so a slider move may take the positions-only path. Vertices `v{i}_{j}`, i < 3. The
// path's middle point `z1` is the including text's (a slider may move it).
inline constexpr const char* swept_triangle_text =
    "point s0 (0.3 0 0) endpoint\npoint s1 (0 0.6 0) endpoint\npoint s2 (-0.3 -0.15 0) endpoint\n"
    "polyline tri (s0 s1 s2) isloop endpolyline\n"
    "point z0 (0 0 0) endpoint\npoint z2 (0.5 0 2) endpoint\n"
    "polyline path (z0 z1 z2) endpolyline\n"
    "sweep sw crosssection tri begincap endcap endcrosssection path path endpath endsweep\n";

// The oracle of a slider's fast paths (vertices moved alone, placements made again): a document whose
// sliders were moved against the same text read from scratch at those values, bit for bit. Compares the
// scene's combined soup (positions, faces in corner order, names, face colours) and the document's
// pipeline input, which takes only the positions when the scene says only vertices moved.
void check_same_as_fresh(const SceneDocument& moved, const std::string& fresh_text);

}  // namespace nome::test
