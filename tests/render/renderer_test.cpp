#include <catch2/catch.hpp>

#include <array>
#include <vector>

#include "render/framebuffer.hpp"
#include "render/image_diff.hpp"
#include "render/offscreen_context.hpp"
#include "render/render_support.hpp"
#include "render/renderer.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

render::SnapshotOptions looking_from(double azimuth, double elevation) {
  render::SnapshotOptions options;
  options.views = {{azimuth, elevation}};
  return options;
}

bool is_dark(const std::uint8_t* p) {
  return p[0] < 90 && p[1] < 90 && p[2] < 90;
}

int count_pixels(const render::Image& image, bool (*keep)(const std::uint8_t*)) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += keep(image.pixel(x, y));
  return n;
}

// Two unit squares side by side (the left one face 0), seen from the front in a 160x120 framebuffer.
struct GridView {
  render::OffscreenContext context;
  render::Renderer renderer;
  Mesh grid = build_mesh(test::grid(2, 1));
  render::MeshBuffers buffers{render::build_display_data(grid)};
  render::Framebuffer framebuffer{160, 120};
  render::Renderer::Frame frame = frame_of(grid, framebuffer);

  static render::Renderer::Frame frame_of(const Mesh& mesh, const render::Framebuffer& target) {
    target.bind();
    render::Camera camera;
    camera.set_view(0, 0);
    camera.fit(mesh.positions(), 160.0 / 120.0);
    return render::Renderer::Frame::of(camera, {0, 0}, {160, 120});
  }
};

}  // namespace

TEST_CASE("a one-sided surface shows its back colour and a closed orientable one does not", "[render]") {
  // Whatever the view, a Möbius band shows both sides of its faces; a torus seen from outside only fronts.
  for (auto [az, el] : {std::pair{30.0, 25.0}, {0.0, 0.0}, {120.0, -40.0}}) {
    const test::SideCounts band =
        test::count_sides(test::render_small(build_mesh(test::mobius_band(32, 4)), looking_from(az, el)));
    CHECK(band.front > 1000);
    CHECK(band.back > 1000);
    const test::SideCounts torus =
        test::count_sides(test::render_small(build_mesh(test::torus(24, 12)), looking_from(az, el)));
    CHECK(torus.front > 5000);
    // Only silhouette samples may catch a back-facing triangle exactly at the rim.
    CHECK(torus.back < torus.front / 200);
  }
}

TEST_CASE("back-face policies: own colour, same colour, culled", "[render]") {
  const Mesh grid = build_mesh(test::grid(2, 2));  // faces look towards +Z
  CHECK(test::count_sides(test::render_small(grid, looking_from(0, 0))).front > 10000);
  render::SnapshotOptions behind = looking_from(180, 0);
  CHECK(test::count_sides(test::render_small(grid, behind)).back > 10000);
  behind.display.back_faces = render::BackFacePolicy::same;
  const test::SideCounts same = test::count_sides(test::render_small(grid, behind));
  CHECK(same.back == 0);
  CHECK(same.front > 10000);
  behind.display.back_faces = render::BackFacePolicy::cull;
  CHECK(test::count_sides(test::render_small(grid, behind)).background == 256 * 192);
}

TEST_CASE("the wireframe draws the polygon's edges, not its triangulation's diagonal", "[render]") {
  render::SnapshotOptions options = looking_from(0, 0);
  options.display.draws_wireframe = true;
  options.display.shading = render::Shading::flat;
  const render::Image image = test::render_small(build_mesh(test::grid(1, 1)), options);
  // The fan's diagonal would cross the centre; the quad's four edges cross the middle row twice.
  for (int y = 86; y < 106; ++y)
    for (int x = 118; x < 138; ++x) REQUIRE_FALSE(is_dark(image.pixel(x, y)));
  int runs = 0;
  for (int x = 1; x < image.width; ++x)
    runs += is_dark(image.pixel(x, 96)) && !is_dark(image.pixel(x - 1, 96));
  CHECK(runs == 2);
  CHECK(count_pixels(image, is_dark) > 4 * 150);
}

TEST_CASE("a transparent background keeps the surface opaque", "[render]") {
  render::SnapshotOptions options;
  options.is_transparent = true;
  const render::Image image = test::render_small(build_mesh(test::cube()), options);
  CHECK(image.pixel(0, 0)[3] == 0);
  CHECK(image.pixel(255, 191)[3] == 0);
  CHECK(image.pixel(128, 96)[3] == 255);
}

TEST_CASE("selection tint, thick lines and cube markers for the viewer", "[render]") {
  GridView view;
  auto& [context, renderer, grid, buffers, framebuffer, frame] = view;
  const render::DisplaySettings settings;
  auto draw = [&] {
    renderer.begin(frame, settings.background);
    renderer.draw_mesh(buffers, frame, settings);
    return framebuffer.read(false);
  };
  const render::Image plain = draw();
  const Index selected[] = {0};  // the left square
  buffers.set_selected_faces(selected);
  const render::Image tinted = draw();
  int left = 0, right = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) (x < 80 ? left : right) += plain.pixel(x, y)[1] != tinted.pixel(x, y)[1];
  CHECK(left > 2000);
  CHECK(right == 0);
  CHECK_THROWS(buffers.set_selected_faces(std::vector<Index>{7}));

  render::LineSet line;
  const glm::vec3 points[] = {{0.0f, 0.5f, 0.0f}, {2.0f, 0.5f, 0.0f}};
  line.set_polyline(points, false);
  render::CubeSet cubes;
  const render::CubeMarker marker{{1.0f, 0.5f, 0.0f}, 0.1f, {0.0f, 0.0f, 1.0f}};
  cubes.set({&marker, 1});
  renderer.begin(frame, settings.background);
  renderer.draw_mesh(buffers, frame, settings);
  renderer.draw_lines(line, frame, {0.0f, 1.0f, 0.0f, 1.0f}, 6.0f);
  renderer.draw_cubes(cubes, frame);
  const render::Image overlays = framebuffer.read(false);
  int green_rows = 0;
  for (int y = 0; y < 120; ++y)
    green_rows += overlays.pixel(20, y)[1] == 255 && overlays.pixel(20, y)[0] == 0;
  CHECK(green_rows >= 5);
  CHECK(green_rows <= 8);
  const std::uint8_t* middle = overlays.pixel(80, 60);
  CHECK(middle[2] > middle[0] + 60);  // the blue cube sits on top of the line
}

TEST_CASE("vertex markers are sized by the local edge length", "[render]") {
  const Mesh small = build_mesh(test::grid(2, 2));
  PolygonSoup big_soup = test::grid(2, 2);
  for (Vec3& p : big_soup.positions) p *= 10.0;
  const Mesh big = build_mesh(big_soup);
  const Index corner_and_centre[] = {0, 4};
  const auto a = render::vertex_markers(small, corner_and_centre, {1, 0, 0});
  const auto b = render::vertex_markers(big, corner_and_centre, {1, 0, 0});
  REQUIRE(a.size() == 2);
  CHECK(a[1].center == glm::vec3(1, 1, 0));
  CHECK(a[0].half_size > 0.05f);
  CHECK(a[0].half_size < 0.5f);
  CHECK(b[0].half_size == Approx(10 * a[0].half_size));
  CHECK_THROWS(render::vertex_markers(small, std::vector<Index>{99}, {1, 0, 0}));
}

TEST_CASE("the mesh shader compiles and draws for every set of features", "[render]") {
  // Each set of features is its own program (shaders/mesh.frag): a combination the others never use
  // must compile too.
  GridView view;
  auto& [context, renderer, grid, buffers, framebuffer, frame] = view;
  const std::array<std::uint8_t, 4> plain{0, 0, 0, 0}, red{255, 0, 0, 255};
  for (unsigned features = 0; features < 64; ++features) {
    INFO("features " << features);
    render::DisplaySettings settings;
    settings.shading = features & 1u ? render::Shading::flat : render::Shading::smooth;
    settings.back_faces = features & 2u ? render::BackFacePolicy::different : render::BackFacePolicy::same;
    const std::array<std::uint8_t, 4> colors[] = {features & 4u ? red : plain, plain};
    buffers.set_face_colors(colors);
    buffers.set_selected_faces(features & 8u ? std::vector<Index>{1} : std::vector<Index>{});
    settings.fills_section = features & 16u;
    settings.section_plane = features & 48u ? glm::vec4(-1.0f, 0.0f, 0.0f, 0.5f) : glm::vec4(0.0f);
    renderer.begin(frame, settings.background);
    CHECK_NOTHROW(renderer.draw_mesh(buffers, frame, settings));
    const render::Image image = framebuffer.read(false);
    const int drawn = count_pixels(image, [](const std::uint8_t* p) { return p[0] < 250 || p[2] < 250; });
    CHECK(drawn > 1000);
  }
}

TEST_CASE("the web's shaders (GLSL ES 3.00) draw what the desktop's draw", "[render]") {
  // Mesa's desktop context compiles GLSL ES 3.00 as well: every program the web build uses, drawn here.
  const render::OffscreenContext context;
  const render::Framebuffer framebuffer(200, 150);
  framebuffer.bind();
  const Mesh band = build_mesh(test::mobius_band(24, 3));
  render::MeshBuffers buffers(render::build_display_data(band));
  const Index selected[] = {2, 3};
  buffers.set_selected_faces(selected);
  std::vector<std::array<std::uint8_t, 4>> colors(band.num_faces(), {0, 0, 0, 0});
  colors[5] = {40, 200, 90, 255};
  buffers.set_face_colors(colors);
  render::LineSet lines;
  const glm::vec3 points[] = {{-1.0f, 0.0f, 0.0f}, {1.0f, 0.2f, 0.3f}, {0.0f, 1.0f, 0.0f}};
  const std::uint32_t segments[] = {0, 1, 1, 2};
  const glm::vec4 line_colors[] = {
      {1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f, 1.0f}};
  lines.set(points, segments, line_colors);
  render::CubeSet cubes;
  const render::CubeMarker marker{{0.0f, 0.0f, 0.0f}, 0.1f, {0.0f, 0.0f, 1.0f}};
  cubes.set({&marker, 1});
  render::Camera camera;
  camera.set_view(30, 25);
  camera.fit(band.positions(), 200.0 / 150.0);
  const auto frame = render::Renderer::Frame::of(camera, {0, 0}, {200, 150});
  for (const bool is_cut : {false, true}) {
    render::DisplaySettings settings;
    settings.shading = is_cut ? render::Shading::flat : render::Shading::smooth;
    settings.draws_wireframe = settings.draws_borders = settings.draws_mobius_edges = true;
    settings.section_plane = is_cut ? glm::vec4(1.0f, 0.0f, 0.0f, -0.2f) : glm::vec4(0.0f);
    settings.fills_section = is_cut;
    auto draw = [&](render::GlslDialect dialect) {
      const render::Renderer renderer(dialect);
      renderer.begin(frame, settings.background);
      renderer.draw_mesh(buffers, frame, settings);
      renderer.draw_lines(lines, frame, {0.0f, 1.0f, 0.0f, 1.0f}, 4.0f);
      renderer.draw_cubes(cubes, frame);
      return framebuffer.read(false);
    };
    const render::Image desktop = draw(render::GlslDialect::desktop);
    CHECK(render::compare_images(desktop, draw(render::GlslDialect::es), 2).differing_pixels == 0);
  }
}
