// Colours given to instances from the viewer (report 8.4): an instance statement names a surface.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "nome/error.hpp"
#include "nome/scene/scene.hpp"
#include "scene/value_change.hpp"

namespace nome::scene {

std::optional<std::string> Scene::instance_of_face(const std::string& face_name) const {
  std::optional<std::string> best;
  for (const Placement& p : placements_) {
    if (p.statement == no_index || !is_leaf(p) || p.path.size() >= face_name.size()) continue;
    if (face_name.compare(0, p.path.size(), p.path) != 0 || face_name[p.path.size()] != '_') continue;
    if (!best || p.path.size() > best->size()) best = p.path;
  }
  return best;
}

Index Scene::placement_of_instance(const std::string& path) const {
  for (Index p = 0; p < placements_.size(); ++p)
    if (placements_[p].path == path && placements_[p].statement != no_index) return p;
  throw InvalidInputError("no instance '" + path + "' in the scene");
}

std::optional<std::string> Scene::instance_surface(const std::string& path) const {
  const InstanceDecl* decl = statement(placements_[placement_of_instance(path)]);
  if (!decl->surface) return std::nullopt;
  return decl->surface->text;
}

void Scene::set_instance_surface(const std::string& path, const std::optional<std::string>& surface) {
  if (surface && !surfaces_.count(*surface)) throw InvalidInputError("no surface '" + *surface + "'");
  const Placement& p = placements_[placement_of_instance(path)];
  const Index group = p.group, at = p.statement;
  InstanceDecl& decl = group == no_index ? ast_.instances[at] : ast_.groups[group].instances[at];
  std::optional<Name> previous =
      std::exchange(decl.surface, surface ? std::optional(Name{*surface, {}}) : std::nullopt);
  // Only the colours of the pieces under that statement (every placement of it) change: they alone are
  // made again.
  std::vector<Index> under;
  for (Index i = 0; i < placements_.size(); ++i) {
    if (!is_leaf(placements_[i])) continue;
    for (Index a = i; a != no_index; a = placements_[a].parent)
      if (placements_[a].group == group && placements_[a].statement == at) {
        under.push_back(i);
        break;
      }
  }
  ValueChange change(*this);
  std::vector<Diagnostic> errors;
  const auto over_budget = change.remake_placements(under, errors);
  if (!errors.empty() || over_budget) {
    decl.surface = std::move(previous);
    change.roll_back();
    if (over_budget) throw BudgetError(*over_budget);
    throw SceneError(std::move(errors));
  }
  has_only_moved_vertices_ = false;
  change.assemble();
}

void Scene::set_instance_color(const std::string& path, Color color) {
  auto byte = [](float c) { return int(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  char name[16];
  std::snprintf(name, sizeof name, "rgb_%02x%02x%02x", byte(color.r), byte(color.g), byte(color.b));
  // A surface of that name holds that colour (made here, or by the user: then a suffix tells them apart).
  std::string surface = name;
  for (int k = 2;; ++k) {
    const auto it = surfaces_.find(surface);
    if (it == surfaces_.end()) {
      SurfaceDecl decl;
      decl.name = Name{surface, {}};
      for (int i = 0; i < 3; ++i) decl.rgb[i].literal = color[i];
      surfaces_[surface] = Index(ast_.surfaces.size());
      ast_.surfaces.push_back(std::move(decl));
      break;
    }
    const SurfaceDecl& existing = ast_.surfaces[it->second];
    bool is_same = true;
    for (int i = 0; i < 3; ++i)
      is_same = is_same && existing.rgb[i].expr == no_index && existing.rgb[i].literal == color[i];
    if (is_same) break;
    surface = std::string(name) + "_" + std::to_string(k);
  }
  set_instance_surface(path, surface);
}

}  // namespace nome::scene
