// Where a placed vertex or instance gets its position: what an editor that drags it must change.
#include <algorithm>

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

VertexOrigin Scene::vertex_origin(const std::string& full_name) const {
  const auto found = find_placed_vertex(full_name);
  if (!found) throw InvalidInputError("no vertex '" + full_name + "' in the scene");
  std::optional<VertexRef> ref = VertexRef{found->placement, found->vertex};
  VertexOrigin origin;
  origin.name = full_name;
  origin.position = placements_[ref->placement].world.soup.positions[ref->vertex];
  origin.parameters = placements_[ref->placement].reads;
  // A copied vertex is its source's world position carried by the copying placement's matrix; the chain
  // ends at a point statement or at a definition that makes its own vertices.
  for (std::size_t depth = 0; depth <= placements_.size(); ++depth) {
    const Placement& p = placements_[ref->placement];
    ParameterReads reads;
    origin.point_to_world = origin.point_to_world * world_matrix(ref->placement, reads);
    std::optional<VertexRef> source;
    if (!p.copied_from.empty()) source = p.copied_from[ref->vertex];
    const std::string local = p.world.soup.vertex_names[ref->vertex].substr(p.path.size() + 1);
    if (!source && points_.count(local)) {
      origin.point = points_.at(local);
      const PointDecl& point = ast_.points[*origin.point];
      origin.statement = point.name.location;
      origin.statement_text = "point '" + point.name.text + "'";
      break;
    }
    if (!source && p.references) {
      std::vector<Diagnostic> errors;
      if (const VertexRef* found = lookup_vertex({local, {}}, errors)) source = *found;
    }
    if (!source) {
      if (p.target.kind != consolidated_kind) {
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
    ref = *source;
  }
  sort_unique(origin.parameters);
  return origin;
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
