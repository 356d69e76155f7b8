#include <catch2/catch.hpp>

#include "nome/error.hpp"
#include "render/gl.hpp"
#include "render/image_diff.hpp"
#include "render/offscreen_context.hpp"
#include "render/render_support.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

void require_core_33() {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  CHECK(major * 10 + minor >= 33);
  CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
}

render::Image render_with(render::Backend backend, const Mesh& mesh) {
  const render::OffscreenContext context(backend);
  render::SnapshotOptions options;
  options.width = 160;
  options.height = 120;
  return render::render_snapshot(mesh, options);
}

}  // namespace

TEST_CASE("EGL gives a GL 3.3 core context with no display and no GPU", "[render]") {
  const render::OffscreenContext context(render::Backend::egl);
  CHECK(context.platform().rfind("EGL", 0) == 0);
  CHECK(context.description().find("OpenGL") != std::string::npos);
  require_core_33();
}

TEST_CASE("OSMesa gives a GL 3.3 core context", "[render]") {
  const render::OffscreenContext context(render::Backend::osmesa);
  CHECK(context.platform() == "OSMesa");
  require_core_33();
}

TEST_CASE("the EGL device fallback gives a GL 3.3 core context", "[render]") {
  const render::OffscreenContext context(render::Backend::egl_device);
  CHECK(context.platform() == "EGL device");
  require_core_33();
}

TEST_CASE("every backend draws the same picture", "[render]") {
  const Mesh band = build_mesh(test::mobius_band(24, 3));
  const render::Image egl = render_with(render::Backend::egl, band);
  CHECK(test::count_sides(egl).front > 500);
  for (const render::Backend other : {render::Backend::egl_device, render::Backend::osmesa}) {
    const render::ImageDifference d = render::compare_images(egl, render_with(other, band), 8);
    REQUIRE(d.same_size);
    CHECK(d.differing_fraction < 0.002);
  }
}

TEST_CASE("backend names", "[render]") {
  CHECK(render::parse_backend("egl") == render::Backend::egl);
  CHECK(render::parse_backend("osmesa") == render::Backend::osmesa);
  CHECK(render::parse_backend("egl-device") == render::Backend::egl_device);
  CHECK_THROWS_AS(render::parse_backend("vulkan"), InvalidInputError);
}
