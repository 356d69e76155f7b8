// Where a placed vertex or instance gets its position: what an editor that drags it must change.
#include <algorithm>
#include <limits>
#include <unordered_map>

#include <glm/matrix.hpp>

#include "nome/error.hpp"
#include "nome/scene/scene.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/index_sets.hpp"

namespace nome::scene {

std::optional<PlacedVertex> Scene::find_placed_vertex(const std::string& full_name) const {
  for (Index p = 0; p < placements_.size(); ++p) {
    const Placement& placement = placements_[p];
    if (!is_leaf(placement) || !full_name.starts_with(placement.path + "_")) continue;
    const std::vector<std::string>& names = placement.world.soup.vertex_names.list();
    const auto it = std::find(names.begin(), names.end(), full_name);
    if (it != names.end()) return PlacedVertex{p, Index(it - names.begin())};
  }
  return std::nullopt;
}

std::optional<Scene::VertexRef> Scene::copy_source(VertexRef ref) const {
  const Placement& p = placements_[ref.placement];
  if (!p.copied_from.empty()) return p.copied_from[ref.vertex];
  if (!p.references) return std::nullopt;
  // A placement that copies some of its vertices: those not named for a point of its own.
  const std::string local = p.world.soup.vertex_names[ref.vertex].substr(p.path.size() + 1);
  if (points_.count(local)) return std::nullopt;
  std::vector<Diagnostic> errors;
  const VertexRef* found = lookup_vertex({local, {}}, errors);
  return found ? std::optional(*found) : std::nullopt;
}

VertexOrigin Scene::vertex_origin(const std::string& full_name) const {
  const auto found = find_placed_vertex(full_name);
  if (!found) throw InvalidInputError("no vertex '" + full_name + "' in the scene");
  VertexRef ref{found->placement, found->vertex};
  VertexOrigin origin;
  origin.name = full_name;
  origin.position = position(*found);
  origin.parameters = placements_[ref.placement].reads;
  // A copied vertex is its source's world position carried by the copying placement's matrix; the chain
  // ends at a point statement or at a definition that makes its own vertices.
  for (std::size_t depth = 0; depth <= placements_.size(); ++depth) {
    const Placement& p = placements_[ref.placement];
    ParameterReads reads;
    origin.point_to_world = origin.point_to_world * world_matrix(ref.placement, reads);
    if (const auto source = copy_source(ref)) {
      ref = *source;
      continue;
    }
    const std::string local = p.world.soup.vertex_names[ref.vertex].substr(p.path.size() + 1);
    if (points_.count(local)) {
      origin.point = points_.at(local);
      const PointDecl& point = ast_.points[*origin.point];
      origin.statement = point.name.location;
      origin.statement_text = "point '" + point.name.text + "'";
    } else if (p.target.kind != consolidated_kind) {
      const StatementKind& kind = statement_kinds()[p.target.kind];
      std::vector<DeclaredName> names;
      kind.declare(ast_, p.target.kind, names);
      for (const DeclaredName& d : names)
        if (d.decl == p.target.index) {
          origin.statement = d.name->location;
          origin.statement_text = std::string(kind.keyword) + " '" + d.name->text + "'";
        }
    }
    break;
  }
  sort_unique(origin.parameters);
  return origin;
}

std::vector<Vec3> Scene::positions_with(std::span<const PlacedVertex> vertices,
                                        std::span<const std::pair<ParameterId, double>> values) {
  const std::vector<double> kept = values_;
  for (const auto& [id, value] : values) values_[id.index()] = value;
  std::unordered_map<Index, Evaluated> evaluated;
  std::vector<Vec3> out;
  for (const PlacedVertex& v : vertices) {
    VertexRef ref{v.placement, v.vertex};
    glm::dmat4 carried(1.0);
    for (std::size_t depth = 0; depth <= placements_.size(); ++depth) {
      const auto source = copy_source(ref);
      if (!source) break;
      ParameterReads reads;
      carried = carried * world_matrix(ref.placement, reads);
      ref = *source;
    }
    auto it = evaluated.find(ref.placement);
    if (it == evaluated.end()) {
      // Evaluating a placement notes its colour and handedness on it: kept as the scene's values give them.
      Placement& p = placements_[ref.placement];
      const auto color = p.color;
      const bool is_mirrored = p.is_mirrored, colors_own_faces = p.colors_own_faces;
      std::vector<Diagnostic> errors;
      it = evaluated.emplace(ref.placement, evaluate_placement(ref.placement, errors)).first;
      p.color = color;
      p.is_mirrored = is_mirrored;
      p.colors_own_faces = colors_own_faces;
    }
    const Buffer<Vec3>& positions = it->second.piece.soup.positions;
    out.push_back(ref.vertex < positions.size() ? Vec3(carried * glm::dvec4(positions[ref.vertex], 1.0))
                                                : Vec3(std::numeric_limits<double>::quiet_NaN()));
  }
  values_ = kept;
  return out;
}

InstanceOrigin Scene::instance_origin(const std::string& path) const {
  const Index placement = placement_of_instance(path);
  const Placement& p = placements_[placement];
  InstanceOrigin origin;
  origin.path = path;
  origin.group = p.group;
  origin.statement = p.statement;
  ParameterReads reads;
  if (p.parent != no_index) origin.parent_to_world = world_matrix(p.parent, reads);
  origin.position = Vec3(world_matrix(placement, reads) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  return origin;
}

const InstanceDecl& Scene::instance_statement(const InstanceOrigin& origin) const {
  return origin.group == no_index ? ast_.instances[origin.statement]
                                  : ast_.groups[origin.group].instances[origin.statement];
}

}  // namespace nome::scene
