#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "nome/mesh/types.hpp"
#include "nome/scene/diagnostic.hpp"
#include "nome/scene/ids.hpp"

namespace nome::scene {

// A vertex of a placement, found by its full name once and read again after slider moves that keep the
// faces (Scene::find_placed_vertex, Scene::position).
struct PlacedVertex {
  Index placement = no_index;
  Index vertex = no_index;
};

// How a placed vertex gets its position, for an editor that moves it: the point statement whose numbers
// give it (through the placements that copy it: a mesh's face naming another instance's vertex), the
// matrix from that point's coordinates to the world, and the sliders its position reads.
struct VertexOrigin {
  std::string name;  // its full hierarchical name
  Vec3 position{0.0};
  std::optional<Index> point;  // of SceneAst::points: the statement that gives its coordinates, if one does
  glm::dmat4 point_to_world{1.0};
  std::vector<ParameterId> parameters;  // sorted
  // The statement that makes it (the point, or the generator's definition) and what it is ("point 'p1'",
  // "funnel 'fun'"), for messages.
  SourceLocation statement;
  std::string statement_text;
};

// How a placed instance is transformed, for an editor that moves it: its statement and the matrices on
// both sides of its own transforms.
struct InstanceOrigin {
  std::string path;
  Index group = no_index;  // the group its statement stands in (no_index: top level)
  Index statement = no_index;
  glm::dmat4 parent_to_world{1.0};  // the placements above it
  Vec3 position{0.0};               // where its origin lands in the world
};

}  // namespace nome::scene
