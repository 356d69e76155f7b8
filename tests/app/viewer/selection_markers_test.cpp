// What a selection draws: the markers and lines show_selection hands the renderer, recorded.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include "render/scene_renderer.hpp"
#include "support/shapes.hpp"
#include "viewer/view/picking.hpp"

using namespace nome;
using namespace nome::viewer;

namespace {

class RecordingRenderer final : public render::SceneRenderer {
 public:
  std::vector<render::CubeMarker> markers;
  std::vector<Index> selected_faces;

  void set_mesh(const render::MeshDisplayData&) override {}
  void set_face_colors(std::span<const std::array<std::uint8_t, 4>>) override {}
  void set_selected_faces(std::span<const Index> faces) override {
    selected_faces.assign(faces.begin(), faces.end());
  }
  void set_markers(std::span<const render::CubeMarker> m) override { markers.assign(m.begin(), m.end()); }
  void set_lines(render::Overlay, std::span<const glm::vec3>, std::span<const std::uint32_t>,
                 std::span<const glm::vec4>) override {}
  void draw(const render::Camera&, glm::ivec2, const render::PixelRect&,
            const render::DisplaySettings&) override {}
  render::Image read_pixels(glm::ivec2) const override { return {}; }
};

// The markers centred on `p`.
std::vector<render::CubeMarker> at(const std::vector<render::CubeMarker>& markers, const Vec3& p) {
  std::vector<render::CubeMarker> found;
  for (const render::CubeMarker& m : markers)
    if (glm::length(glm::dvec3(m.center) - p) < 1e-5) found.push_back(m);
  return found;
}

}  // namespace

TEST_CASE("the first end of a partial border being picked is marked until the other end comes", "[app]") {
  const Mesh mesh = build_mesh(test::grid(3, 2));
  auto borders = std::make_shared<const BorderLookup>(mesh);
  const PickableRims rims = pickable_rims(RimLines{}, mesh, borders);
  const auto loop = borders->whole_loop_from(0);
  Selection selection;
  selection.set_mode(SelectionMode::border_partial);
  CHECK_FALSE(selection.click_border_vertex(*borders, loop[0]).empty());  // "pick the other end"
  RecordingRenderer renderer;
  const glm::vec3 color(1, 0, 0), rim_color(0, 0, 1);
  show_selection(renderer, mesh, rims, selection, color, rim_color);
  const auto waiting = at(renderer.markers, mesh.position(loop[0]));
  REQUIRE(waiting.size() == 1);
  CHECK(waiting[0].color != color);  // its own colour: waiting for the other end
  CHECK(waiting[0].half_size > 0);
  CHECK_FALSE(selection.click_border_vertex(*borders, loop[3]).empty());  // "pick a side"
  show_selection(renderer, mesh, rims, selection, color, rim_color);
  CHECK(at(renderer.markers, mesh.position(loop[0])).size() == 1);
  CHECK(at(renderer.markers, mesh.position(loop[3])).size() == 1);
  CHECK(selection.click_border_vertex(*borders, loop[6]).empty());
  show_selection(renderer, mesh, rims, selection, color, rim_color);
  CHECK(selection.pending_ends().empty());
  CHECK(at(renderer.markers, mesh.position(loop[0])).empty());  // a partial border has no matching point
}
