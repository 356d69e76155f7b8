#pragma once

#include <span>
#include <string>

#include "nome/mesh/types.hpp"

namespace nome::test {

// Compares two point sets regardless of order: near every point of `a` (within `relative_tolerance`
// times b's bounding-box diagonal), b must hold `multiplicity` times as many points as a does, and b must
// hold a.size() * multiplicity points. Returns "" on success, else what differs.
std::string compare_point_sets(std::span<const Vec3> a, std::span<const Vec3> b, double relative_tolerance,
                               int multiplicity = 1);

}  // namespace nome::test
