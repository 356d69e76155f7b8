#include "scene/value_change.hpp"

#include <algorithm>

#include "scene/index_sets.hpp"

namespace nome::scene {

ValueChange::ValueChange(Scene& scene, ParameterId parameter, double value)
    : scene_(scene), parameter_(parameter), old_value_(scene.values_[parameter.index()]) {
  set(value);
}

void ValueChange::set(double value) {
  scene_.values_[parameter_.index()] = value;
  if (scene_.parameters_.contains(parameter_)) scene_.parameters_[parameter_].value = value;
}

std::optional<std::string> ValueChange::reevaluate(std::vector<Diagnostic>& errors) {
  std::vector<Index> remade;
  for (Index i = 0; i < scene_.placements_.size(); ++i) {
    const Scene::Placement& p = scene_.placements_[i];
    if (!scene_.is_leaf(p) || !std::binary_search(p.reads.begin(), p.reads.end(), parameter_)) continue;
    Scene::Moved previous;
    if (p.references)
      copies_.push_back(i);
    else if (scene_.move_vertices(i, previous))
      moved_.emplace_back(i, std::move(previous));
    else
      remade.push_back(i);
  }
  auto over_budget = remake(remade, errors);
  if (errors.empty() && !over_budget) over_budget = remake(copies_to_remake(), errors);
  return over_budget;
}

std::optional<std::string> ValueChange::remake(const std::vector<Index>& placements,
                                               std::vector<Diagnostic>& errors) {
  const size_t first = remade_.size();
  for (Index i : placements) {
    const Scene::Placement& p = scene_.placements_[i];
    remade_.push_back(
        {i, p.world, p.reads, p.copied_from, p.color, p.is_mirrored, p.colors_own_faces, p.warnings});
  }
  auto over_budget = scene_.evaluate_all(placements, errors);
  // A placement made again may still have only moved (a generator with no positions of its own).
  for (size_t k = first; k < remade_.size(); ++k)
    if (!has_same_topology(remade_[k].world, scene_.placements_[remade_[k].placement].world))
      new_topology_.push_back(remade_[k].placement);
  return over_budget;
}

std::vector<Index> ValueChange::copies_to_remake() {
  std::vector<Index> remade;
  for (Index i : copies_) {
    const std::vector<Scene::VertexRef>& sources = scene_.placements_[i].copied_from;
    const bool has_new_source = std::any_of(sources.begin(), sources.end(), [&](const Scene::VertexRef& ref) {
      return std::find(new_topology_.begin(), new_topology_.end(), ref.placement) != new_topology_.end();
    });
    Scene::Moved previous;
    if (!has_new_source && scene_.move_copied_vertices(i, previous))
      moved_.emplace_back(i, std::move(previous));
    else
      remade.push_back(i);
  }
  return remade;
}

void ValueChange::roll_back() {
  if (parameter_.is_valid()) {
    scene_.values_[parameter_.index()] = old_value_;
    if (scene_.parameters_.contains(parameter_)) scene_.parameters_[parameter_].value = old_value_;
  }
  for (auto& [i, previous] : moved_) {
    scene_.placements_[i].world.soup.positions = std::move(previous.positions);
    scene_.placements_[i].warnings = std::move(previous.warnings);
  }
  for (Kept& kept : remade_) {
    Scene::Placement& p = scene_.placements_[kept.placement];
    p.world = std::move(kept.world);
    p.reads = std::move(kept.reads);
    p.copied_from = std::move(kept.copied_from);
    p.color = kept.color;
    p.is_mirrored = kept.is_mirrored;
    p.colors_own_faces = kept.colors_own_faces;
    p.warnings = std::move(kept.warnings);
  }
  scene_.is_vertex_index_current_ = false;
}

std::vector<InstanceId> ValueChange::assemble() const {
  std::vector<Index> tops, remade_tops;
  for (const Kept& kept : remade_) remade_tops.push_back(scene_.placements_[kept.placement].top);
  sort_unique(remade_tops);
  tops = remade_tops;
  for (const auto& [i, previous] : moved_) tops.push_back(scene_.placements_[i].top);
  sort_unique(tops);
  std::vector<InstanceId> changed;
  for (Index t : tops) {
    if (scene_.shown_deletions().empty() && !std::binary_search(remade_tops.begin(), remade_tops.end(), t))
      scene_.assemble_positions(t);
    else
      scene_.assemble(t);
    changed.push_back(InstanceId(t));
  }
  return changed;
}

}  // namespace nome::scene
