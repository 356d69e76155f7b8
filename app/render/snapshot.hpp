#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "nome/mesh/mesh.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/image.hpp"
#include "render/rim_segments.hpp"

namespace nome::render {

struct ViewAngle {
  double azimuth = 30.0;    // degrees about +Y
  double elevation = 25.0;  // degrees above the XZ plane
};

struct SnapshotOptions {
  int width = 1024;
  int height = 768;
  // One view fills the picture; several become a contact sheet of tiles, row by row.
  std::vector<ViewAngle> views{ViewAngle{}};
  // Framing: by default each view is fitted to the whole mesh; a fixed target and/or distance keep the
  // framing steady across renders (an animation over a slider, a comparison of stages).
  std::optional<glm::dvec3> target;
  std::optional<double> distance;
  DisplaySettings display;
  bool is_transparent = false;  // background alpha 0 (the PNG keeps an alpha channel)
  int samples = 4;              // multisampling
  Lens lens;                    // perspective (the default) or orthographic, as a scene's camera asks
  // The scene's polylines, drawn over the mesh in display.rim_color as the viewer draws them.
  LineSegments rims;
};

// What a view frames: the mesh's vertices and the polylines' points.
std::vector<Vec3> framed_points(const Mesh& mesh, const SnapshotOptions& options);

// The views of several tiles: `count` azimuths evenly around the first view, same elevation.
std::vector<ViewAngle> views_around(ViewAngle first, int count);

// Renders the mesh with the shared renderer into an offscreen framebuffer, each view framed to the
// whole mesh. Needs a current context (OffscreenContext).
Image render_snapshot(const Mesh& mesh, const SnapshotOptions& options);

}  // namespace nome::render
