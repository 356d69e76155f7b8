#include "app/viewer_support.hpp"

#include <glm/geometric.hpp>

#include "nome/query/pick.hpp"
#include "render/camera.hpp"

namespace nome::test {

CommandResult run_viewer(const std::string& arguments) {
  // A state folder of its own: a recovery file a crashed viewer left in the user's would be offered.
  const std::string state = private_scratch_dir("viewer_state");
  // An authority file of its own: without one xvfb-run makes a temporary folder and, when removing it
  // fails, exits 5 in place of the viewer's status.
  static int sessions = 0;
  const std::string auth = private_scratch_dir("xvfb") + "/auth-" + std::to_string(sessions++);
  return run_nome_prefixed(
      "env XDG_STATE_HOME=" + state + " xvfb-run -a -f " + auth + " -s \"-screen 0 1280x800x24\"", arguments);
}

ScreenProjection viewer_projection(const Mesh& mesh, double azimuth, double elevation) {
  render::Camera camera;
  const double aspect = double(viewer_width) / double(viewer_height);
  camera.set_view(azimuth, elevation);
  camera.fit(mesh.positions(), aspect);
  return camera.screen_projection({viewer_width, viewer_height});
}

std::optional<glm::dvec2> click_position(const Mesh& mesh, const ScreenProjection& projection, Index v) {
  const TriangleBvh bvh(mesh);
  const auto pixel = project_to_pixel(projection, mesh.position(v));
  if (!pixel) return std::nullopt;
  // A little towards the middle of a face at v, so that the ray lands on the surface.
  for (Index c : mesh.vertex_corners(v)) {
    Vec3 centre(0.0);
    const Index f = mesh.corner_face(c);
    for (Index u : mesh.face_vertices(f)) centre += mesh.position(u);
    centre /= double(mesh.face_degree(f));
    const auto inside = project_to_pixel(projection, centre);
    if (!inside) continue;
    const glm::dvec2 towards = glm::dvec2(*inside) - glm::dvec2(*pixel);
    if (glm::length(towards) < 1e-9) continue;
    const glm::dvec2 click = glm::round(glm::dvec2(*pixel) + 3.0 * glm::normalize(towards));
    if (pick_vertex(mesh, bvh, projection, click, 8.0) == v) return click;
  }
  return std::nullopt;
}

}  // namespace nome::test
