#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/query/border_lookup.hpp"
#include "nome/query/rim_pick.hpp"
#include "render/cube_set.hpp"
#include "viewer/view/selection.hpp"

namespace nome::viewer {

// The scene's rim lines (report 6.3) as clicks see them: a cube at every vertex, numbered after the shown
// mesh's vertices (rim vertex k is id mesh.num_vertices() + k), so that a selection holds one kind of
// id and a rim vertex counts wherever a vertex does; and the shown mesh's borders with the rim lines
// added, for the border modes.
struct PickableRims {
  RimLines lines;
  std::vector<double> half_sizes;
  Index first_id = 0;  // the shown mesh's vertex count
  std::shared_ptr<const BorderLookup> borders;

  bool is_rim(Index v) const { return v >= first_id && v - first_id < lines.num_vertices(); }
  const Vec3& position(const Mesh& mesh, Index v) const {
    return is_rim(v) ? lines.positions[v - first_id] : mesh.position(v);
  }
  // The vertex's hierarchical name, as edits refer to it.
  std::string name(const Mesh& mesh, Index v) const;
};

// The rim lines numbered after `mesh`'s vertices, with `borders` (the mesh's) extended by them (shared
// as it is when there are no rim lines).
PickableRims pickable_rims(RimLines lines, const Mesh& mesh, std::shared_ptr<const BorderLookup> borders);

// The names along a selected border as the document's zipper reads them (a loop from its first vertex,
// that vertex again at the end).
std::vector<std::string> chain_names(const Mesh& mesh, const PickableRims& rims,
                                     const Selection::Border& border);
bool touches_rim(const PickableRims& rims, const Selection::Border& border);

// A cube at every rim vertex (rim colour, selected ones in the selection's), sized as the report says.
std::vector<render::CubeMarker> rim_markers(const PickableRims& rims, const std::vector<Index>& selected,
                                            const glm::vec3& color, const glm::vec3& selected_color);

}  // namespace nome::viewer
