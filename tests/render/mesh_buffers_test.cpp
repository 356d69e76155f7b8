#include <catch2/catch.hpp>

#include "nome/error.hpp"
#include "render/framebuffer.hpp"
#include "render/mesh_buffers.hpp"
#include "render/offscreen_context.hpp"
#include "render/scene_renderer.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// The data of `mesh` reusing `topology` (the stage pipeline's result of a slider that moved vertices).
render::MeshDisplayData moved(const Mesh& mesh, std::shared_ptr<const render::DisplayTopology> topology) {
  render::MeshDisplayData data;
  data.topology = std::move(topology);
  auto positions = std::make_shared<render::DisplayPositions>();
  render::build_display_positions(mesh, *data.topology, *positions);
  data.positions = std::move(positions);
  data.face_colors = render::display_face_colors(mesh);
  return data;
}

}  // namespace

TEST_CASE("moved vertices update the buffers in place, drawn as fresh buffers of the moved mesh",
          "[render]") {
  const render::OffscreenContext context;
  const glm::ivec2 size{160, 120};
  const render::Framebuffer framebuffer(size.x, size.y);
  framebuffer.bind();
  const Mesh before = build_mesh(test::mobius_band(24, 3));
  Mesh after = before;
  for (Vec3& p : after.positions()) p = Vec3(p.x * 1.3, p.y, p.z + 0.3 * p.x * p.x);
  render::Camera camera;
  camera.set_view(30, 25);
  camera.fit(after.positions(), double(size.x) / size.y);
  for (const render::Shading shading : {render::Shading::smooth, render::Shading::flat}) {
    render::DisplaySettings display;
    display.shading = shading;
    display.draws_wireframe = true;
    auto draw = [&](render::SceneRenderer& renderer) {
      renderer.draw(camera, size, {{0, 0}, size}, display);
      return framebuffer.read(false);
    };
    const auto updated = render::make_gl_scene_renderer();
    const render::MeshDisplayData first = render::build_display_data(before);
    updated->set_mesh(first);
    const render::Image old_picture = draw(*updated);
    updated->set_mesh(moved(after, first.topology));
    const auto fresh = render::make_gl_scene_renderer();
    fresh->set_mesh(render::build_display_data(after));
    const render::Image picture = draw(*updated);
    CHECK(picture.rgba == draw(*fresh).rgba);
    CHECK(picture.rgba != old_picture.rgba);
  }
  render::MeshBuffers buffers(render::build_display_data(before));
  CHECK_THROWS_AS(buffers.update_positions(*render::build_display_data(build_mesh(test::cube())).positions),
                  InvalidInputError);
}
