#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "nome/ops/zipper.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "nome/scene/scene.hpp"
#include "render/scene_renderer.hpp"
#include "viewer/session/stage_pipeline.hpp"
#include "viewer/view/rim_picking.hpp"
#include "viewer/view/selection.hpp"

namespace nome::viewer {

// A window pixel within this distance of a vertex picks it.
constexpr double pick_pixels = 8.0;

// A click in the selection's mode on the shown stage: selects or deselects what is under the pixel. A
// rim vertex's cube in front of the surface counts as a vertex in the vertex and border modes.
// Returns the log line saying what happened (empty when nothing is under the pixel).
std::string select_at(Selection& selection, const StageResult& shown, const TriangleBvh& bvh,
                      const PickableRims& rims, const ScreenProjection& projection, glm::dvec2 pixel);

// A click in instance mode: the instance that placed the face under the pixel (report 8.4) is selected,
// or deselected, at any stage (a face of the smoothed solid through the input face it came from). Returns
// the log line.
std::string select_instance(Selection& selection, const StageResult& shown, const TriangleBvh& bvh,
                            const Session* session, const ScreenProjection& projection, glm::dvec2 pixel);

// A selected border as the zipper reads it: whole loops from their first vertex, segments end to end in
// the direction they were picked.
BorderSelection zipper_border(const BorderLookup& borders, const Selection::Border& border);

// The selection's markers (vertex cubes, the first vertex of each whole border), the rim vertices'
// cubes, and border lines. `more` markers (the print check's places) are drawn with them.
void show_selection(render::SceneRenderer& renderer, const Mesh& mesh, const PickableRims& rims,
                    const Selection& selection, const glm::vec3& color, const glm::vec3& rim_color,
                    std::span<const render::CubeMarker> more = {});

// The shown mesh's sharp edges (any weight), drawn in the display's sharp colour.
void show_sharp_edges(render::SceneRenderer& renderer, const Mesh& mesh);

// The colours of the temporary and consolidated faces (edits), painted over the stage's own.
struct EditColors {
  glm::vec3 consolidated{0.62f, 0.42f, 0.86f};
  glm::vec3 temporary{0.30f, 0.76f, 0.42f};
};
// `paints` (face, RGBA) go over both (the print check's findings).
void show_face_colors(render::SceneRenderer& renderer, const StageResult& shown, const EditColors& colors,
                      std::span<const std::pair<Index, std::array<std::uint8_t, 4>>> paints = {});

}  // namespace nome::viewer
