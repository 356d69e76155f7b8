#pragma once

#include "nome/query/rim_pick.hpp"
#include "nome/scene/scene.hpp"

namespace nome::scene {

// Every top-level instance's rim lines with their world positions and full hierarchical vertex names,
// the names edits refer to (a polygon through a rim vertex, a zipper along a rim line).
RimLines scene_rim_lines(const Scene& scene);

// Their positions alone, in the same order: what a slider that only moved vertices changes.
std::vector<Vec3> scene_rim_positions(const Scene& scene);

}  // namespace nome::scene
