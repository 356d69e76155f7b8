#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nome/scene/scene.hpp"

namespace nome::scene {

// One value change of a scene (Scene::change_value), in steps: the placements that read the value move
// their vertices where they can and are made again where they cannot, copies follow their sources, and a
// refused value puts every placement back as it was. Without a value, a change of the text that some
// placements read (an instance's surface) made again in the same steps.
class ValueChange {
 public:
  ValueChange(Scene& scene, ParameterId parameter, double value);
  explicit ValueChange(Scene& scene) : scene_(scene) {}

  // The placements that read the value, moved or made again. Returns the BudgetError message when the
  // face budget stopped the evaluation; `errors` holds the others.
  std::optional<std::string> reevaluate(std::vector<Diagnostic>& errors);
  // These placements made again (a change without a value); as reevaluate() for the rest.
  std::optional<std::string> remake_placements(const std::vector<Index>& placements,
                                               std::vector<Diagnostic>& errors) {
    return remake(placements, errors);
  }
  // The value, the placements and their geometry as before the change.
  void roll_back();
  // Assembles the top-level instances that changed (only their positions where no placement was made
  // again) and returns them.
  std::vector<InstanceId> assemble() const;
  // Whether every placement kept its faces (only positions changed).
  bool has_only_moved() const { return new_topology_.empty(); }

 private:
  // What evaluating a placement changes, to put back when the value is refused.
  struct Kept {
    Index placement;
    Piece world;
    ParameterReads reads;
    std::vector<Scene::VertexRef> copied_from;
    std::optional<Color> color;
    bool is_mirrored;
    bool colors_own_faces;
    std::vector<Diagnostic> warnings;
  };

  void set(double value);
  // Evaluates the placements again, keeping what they were; notes those with other faces now.
  std::optional<std::string> remake(const std::vector<Index>& placements, std::vector<Diagnostic>& errors);
  // The copies of other placements' vertices that cannot follow their sources by moving (a source has
  // other faces now, or the copy has colours of its own); the others are moved.
  std::vector<Index> copies_to_remake();

  Scene& scene_;
  ParameterId parameter_;  // none: a change without a value
  double old_value_ = 0.0;
  std::vector<Index> copies_;  // leaves that copy other placements' vertices, done after their sources
  std::vector<std::pair<Index, Scene::Moved>> moved_;  // with their previous positions and warnings
  std::vector<Kept> remade_;
  std::vector<Index> new_topology_;  // remade placements whose faces changed
};

}  // namespace nome::scene
