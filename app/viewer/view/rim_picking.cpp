#include "viewer/view/rim_picking.hpp"

#include <algorithm>

namespace nome::viewer {

std::string PickableRims::name(const Mesh& mesh, Index v) const {
  if (is_rim(v)) return lines.names[v - first_id];
  return v < mesh.vertex_names().size() ? mesh.vertex_names()[v] : mesh.vertex_label(v);
}

PickableRims pickable_rims(RimLines lines, const Mesh& mesh, std::shared_ptr<const BorderLookup> borders) {
  PickableRims rims;
  // Cubes a fifth of the mean rim edge across: clickable, and clear of their neighbours.
  rims.half_sizes = rim_cube_half_sizes(lines, 0.1);
  rims.first_id = mesh.num_vertices();
  if (lines.num_lines() == 0) {
    rims.borders = std::move(borders);
  } else {
    auto extended = std::make_shared<BorderLookup>(*borders);
    extended->add_rim_lines(lines, rims.first_id);
    rims.borders = std::move(extended);
  }
  rims.lines = std::move(lines);
  return rims;
}

std::vector<std::string> chain_names(const Mesh& mesh, const PickableRims& rims,
                                     const Selection::Border& border) {
  std::vector<std::string> names;
  for (Index v : border.vertices) names.push_back(rims.name(mesh, v));
  if (border.is_loop && !names.empty()) names.push_back(names.front());
  return names;
}

bool touches_rim(const PickableRims& rims, const Selection::Border& border) {
  return std::any_of(border.vertices.begin(), border.vertices.end(), [&](Index v) { return rims.is_rim(v); });
}

std::vector<render::CubeMarker> rim_markers(const PickableRims& rims, const std::vector<Index>& selected,
                                            const glm::vec3& color, const glm::vec3& selected_color) {
  std::vector<render::CubeMarker> markers;
  markers.reserve(rims.lines.num_vertices());
  for (Index k = 0; k < rims.lines.num_vertices(); ++k) {
    const bool is_selected = std::find(selected.begin(), selected.end(), rims.first_id + k) != selected.end();
    markers.push_back({glm::vec3(rims.lines.positions[k]), float(rims.half_sizes[k]),
                       is_selected ? selected_color : color});
  }
  return markers;
}

}  // namespace nome::viewer
