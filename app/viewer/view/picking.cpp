#include "viewer/view/picking.hpp"

#include <algorithm>

#include "nome/mesh/input_faces.hpp"
#include "nome/mesh/named_sharp_edge.hpp"
#include "nome/query/pick.hpp"
#include "nome/query/pick_edge.hpp"
#include "nome/query/rim_pick.hpp"

namespace nome::viewer {
namespace {

bool contains(const std::vector<Index>& items, Index i) {
  return std::find(items.begin(), items.end(), i) != items.end();
}

std::string select_border(Selection& selection, const StageResult& shown, const PickableRims& rims, Index v) {
  const std::size_t before = selection.borders().size();
  const bool has_rims = rims.borders && rims.first_id == shown.mesh->num_vertices();
  std::string hint = selection.click_border_vertex(has_rims ? *rims.borders : *shown.borders, v);
  if (hint.empty() && selection.borders().size() > before) {
    const auto& border = selection.borders().back();
    const bool is_rim = touches_rim(rims, border);
    hint = std::string(is_rim ? (border.is_loop ? "rim line" : "rim line segment")
                              : (border.is_loop ? "border" : "partial border")) +
           " of " + std::to_string(border.vertices.size()) + " vertices selected, from " +
           (is_rim ? rims.name(*shown.mesh, border.vertices.front())
                   : shown.mesh->vertex_label(border.vertices.front()));
  }
  return hint;
}

// The name of the scene face that face f of `shown` came from: through the input face it carries, or its
// own name where the stage keeps the scene's faces without marks.
std::optional<std::string> scene_face_name(const Mesh& shown, const PolygonSoup& input, Index f) {
  if (const std::optional<Index> from = input_face(shown, f)) {
    if (*from < input.face_names.size()) return input.face_names[*from];
    return std::nullopt;
  }
  if (f < shown.face_names().size()) return shown.face_names()[f];
  return std::nullopt;
}

// The vertex under the pixel: a rim vertex whose cube is in front of the surface, else the nearest corner
// of the face under it.
std::optional<Index> vertex_at(const StageResult& shown, const TriangleBvh& bvh, const PickableRims& rims,
                               const ScreenProjection& projection, glm::dvec2 pixel) {
  if (rims.first_id == shown.mesh->num_vertices())
    if (const auto k = pick_rim_vertex(rims.lines, rims.half_sizes, bvh, projection, pixel))
      return rims.first_id + k->index();
  if (const auto v = pick_vertex(*shown.mesh, bvh, projection, pixel, pick_pixels)) return v->index();
  return std::nullopt;
}

}  // namespace

std::string select_at(Selection& selection, const StageResult& shown, const TriangleBvh& bvh,
                      const PickableRims& rims, const ScreenProjection& projection, glm::dvec2 pixel) {
  const Mesh& mesh = *shown.mesh;
  std::string hint;
  if (selection.mode() == SelectionMode::edge) {
    if (const auto picked = pick_edge(mesh, bvh, projection, pixel, pick_pixels)) {
      const Index edge = picked->index();
      selection.click_edge(edge);
      const auto [u, w] = mesh.edge(edge).vertices;
      hint = "edge (" + mesh.vertex_label(u) + ", " + mesh.vertex_label(w) + ")" +
             (mesh.edge_sharpness(edge) > 0 ? ", sharpness " + sharpness_text(mesh.edge_sharpness(edge)) + ","
                                            : "") +
             (contains(selection.edges(), edge) ? " selected" : " deselected");
    }
  } else if (selection.mode() == SelectionMode::face) {
    if (const auto picked = pick_face(bvh, projection, pixel)) {
      const Index face = picked->index();
      selection.click_face(face);
      hint =
          "face " + mesh.face_label(face) + (contains(selection.faces(), face) ? " selected" : " deselected");
    }
  } else if (const auto v = vertex_at(shown, bvh, rims, projection, pixel)) {
    if (selection.mode() == SelectionMode::vertex) {
      selection.click_vertex(*v);
      hint = (rims.is_rim(*v) ? "rim vertex " + rims.name(mesh, *v) : "vertex " + mesh.vertex_label(*v)) +
             (contains(selection.vertices(), *v) ? " selected" : " deselected");
    } else {
      hint = select_border(selection, shown, rims, *v);
    }
  }
  if (!hint.empty() && !is_editable(shown.stage))
    hint += std::string(" in the ") + to_string(shown.stage) +
            " stage (to look; edits need the scene or merged stage)";
  return hint;
}

std::string select_instance(Selection& selection, const StageResult& shown, const TriangleBvh& bvh,
                            const Session* session, const ScreenProjection& projection, glm::dvec2 pixel) {
  const auto face = pick_face(bvh, projection, pixel);
  if (!face) return {};
  const scene::Scene* scene = session ? session->scene() : nullptr;
  const std::optional<std::string> name =
      session ? scene_face_name(*shown.mesh, session->polygons(), face->index()) : std::nullopt;
  const auto path = scene && name ? scene->instance_of_face(*name) : std::nullopt;
  if (!path) return "no instance: instance mode needs a scene file";
  selection.click_instance(*path);
  const auto& selected = selection.instances();
  return "instance " + *path +
         (std::find(selected.begin(), selected.end(), *path) != selected.end() ? " selected" : " deselected");
}

BorderSelection zipper_border(const BorderLookup& borders, const Selection::Border& border) {
  BorderSelection out;
  out.start = border.vertices.front();
  out.end = border.is_loop ? out.start : border.vertices.back();
  if (!border.is_loop && border.vertices.size() > 1) {
    const auto loop = borders.loop_vertices(borders.loop_of(out.start));
    const auto at = std::find(loop.begin(), loop.end(), out.start) - loop.begin();
    out.backwards = loop[(at + 1) % loop.size()] != border.vertices[1];
  }
  return out;
}

void show_selection(render::SceneRenderer& renderer, const Mesh& mesh, const PickableRims& rims,
                    const Selection& selection, const glm::vec3& color, const glm::vec3& rim_color,
                    std::span<const render::CubeMarker> more) {
  // Selected instances show as their faces selected.
  std::vector<Index> faces = selection.faces();
  const auto& face_names = mesh.face_names();
  for (const std::string& path : selection.instances())
    for (Index f = 0; f < face_names.size(); ++f)
      if (face_names[f].size() > path.size() && face_names[f].compare(0, path.size(), path) == 0 &&
          face_names[f][path.size()] == '_')
        faces.push_back(f);
  renderer.set_selected_faces(faces);
  std::vector<Index> marked;
  for (Index v : selection.vertices())
    if (!rims.is_rim(v)) marked.push_back(v);
  // The first vertex of each whole border is the zipper's matching point: marked as a cube.
  for (const auto& border : selection.borders())
    if (border.is_loop && !border.vertices.empty() && !rims.is_rim(border.vertices[0]))
      marked.push_back(border.vertices[0]);
  std::vector<Index> rim_selected = selection.vertices();
  rim_selected.insert(rim_selected.end(), selection.pending_ends().begin(), selection.pending_ends().end());
  std::vector<render::CubeMarker> markers = rim_markers(rims, rim_selected, rim_color, color);
  for (const render::CubeMarker& m : render::vertex_markers(mesh, marked, color)) markers.push_back(m);
  std::vector<Index> pending;
  for (Index v : selection.pending_ends())
    if (!rims.is_rim(v)) pending.push_back(v);
  for (const render::CubeMarker& m : render::vertex_markers(mesh, pending, {0.1f, 0.7f, 0.3f}))
    markers.push_back(m);
  markers.insert(markers.end(), more.begin(), more.end());
  renderer.set_markers(markers);
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> segments;
  for (Index e : selection.edges()) {
    for (Index v : mesh.edge(e).vertices) points.push_back(glm::vec3(mesh.position(v)));
    segments.insert(segments.end(), {std::uint32_t(points.size() - 2), std::uint32_t(points.size() - 1)});
  }
  for (const auto& border : selection.borders()) {
    const std::uint32_t first = std::uint32_t(points.size());
    for (Index v : border.vertices) points.push_back(glm::vec3(rims.position(mesh, v)));
    const std::uint32_t n = std::uint32_t(border.vertices.size());
    for (std::uint32_t i = 0; i + 1 < n; ++i) segments.insert(segments.end(), {first + i, first + i + 1});
    if (border.is_loop && n > 2) segments.insert(segments.end(), {first + n - 1, first});
  }
  renderer.set_lines(render::Overlay::selection, points, segments);
}

void show_sharp_edges(render::SceneRenderer& renderer, const Mesh& mesh) {
  std::vector<glm::vec3> points;
  std::vector<std::uint32_t> segments;
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    if (mesh.edge_sharpness(e) <= 0) continue;
    for (Index v : mesh.edge(e).vertices) points.push_back(glm::vec3(mesh.position(v)));
    segments.insert(segments.end(), {std::uint32_t(points.size() - 2), std::uint32_t(points.size() - 1)});
  }
  renderer.set_lines(render::Overlay::sharp, points, segments);
}

void show_face_colors(render::SceneRenderer& renderer, const StageResult& shown, const EditColors& colors,
                      std::span<const std::pair<Index, std::array<std::uint8_t, 4>>> paints) {
  // Faces keep their order through the scene and merged stages: the edited ones take their colours.
  auto face_colors = shown.display.face_colors;
  const FaceParts& parts = shown.parts;
  if (face_colors.empty()) face_colors.resize(shown.display.topology->num_faces, {0, 0, 0, 0});
  if (is_editable(shown.stage) &&
      face_colors.size() == std::size_t(parts.scene) + parts.consolidated + parts.temporary) {
    auto paint = [&](Index first, Index count, glm::vec3 c) {
      for (Index f = first; f < first + count; ++f)
        face_colors[f] = {std::uint8_t(c.r * 255.0f + 0.5f), std::uint8_t(c.g * 255.0f + 0.5f),
                          std::uint8_t(c.b * 255.0f + 0.5f), 255};
    };
    paint(parts.scene, parts.consolidated, colors.consolidated);
    paint(parts.scene + parts.consolidated, parts.temporary, colors.temporary);
  }
  for (const auto& [face, color] : paints)
    if (face < face_colors.size()) face_colors[face] = color;
  renderer.set_face_colors(face_colors);
}

}  // namespace nome::viewer
