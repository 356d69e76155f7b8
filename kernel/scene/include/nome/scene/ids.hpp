#pragma once

#include <vector>

#include "nome/id.hpp"

namespace nome::scene {

// A value expressions read: a slider (the first ids, Scene::parameters()) or a built-in clock after them.
using ParameterId = Id<struct ParameterKind>;
// A top-level instance (Scene::instances()).
using InstanceId = Id<struct InstanceKind>;
// One placement of a definition: an instance statement at one place in the hierarchy (a group placed
// twice places its statements twice).
using PlacementId = Id<struct PlacementKind>;

// The values an evaluation read, for re-evaluating it when one of them changes.
using ParameterReads = std::vector<ParameterId>;

}  // namespace nome::scene
