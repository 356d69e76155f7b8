#pragma once

#include <span>
#include <vector>

#include "nome/scene/sweep.hpp"

namespace nome::scene {

// Per sample of a path: the tangent (bisecting a corner), the unit direction the path bends towards
// (zero where it runs straight) and the mitre stretch across that bend, 1 / cos(half the turn).
struct PathShape {
  std::vector<Vec3> tangent, bend;
  std::vector<double> stretch;
};
PathShape path_shape(std::span<const Vec3> points, bool is_closed);
// The frames of path_frames() for a path whose shape is known.
std::vector<Frame> frames_of(std::span<const Vec3> points, const PathShape& shape, bool is_closed,
                             FrameKind kind);

}  // namespace nome::scene
