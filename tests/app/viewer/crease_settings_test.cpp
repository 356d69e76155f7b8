// The Stage section's crease method and smooth-triangle rule, changed through the viewer (script `setting`):
// the subdivided stage changes, and equals what the command line makes with the same options.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"

using namespace nome;

namespace {

// A box whose bottom is two triangles, with a crease whose weight changes along it (2.5 then 0.5): the
// Chaikin method evens the weights out where uniform decay does not (seen from the third level), and the
// triangles' smooth rule moves their edge points.
const char* const creased_box_text =
    "point a (0 0 0) endpoint point b (1 0 0) endpoint point c (1 1 0) endpoint point d (0 1 0) endpoint\n"
    "point e (0 0 1) endpoint point f (1 0 1) endpoint point g (1 1 1) endpoint point h (0 1 1) endpoint\n"
    "mesh box\n"
    "  face b1 (a d c) endface face b2 (a c b) endface face top (e f g h) endface face front (a b f e) "
    "endface\n"
    "  face back (c d h g) endface face left (a e h d) endface face right (b c g f) endface\n"
    "  sharp 2.5 (e f g) endsharp sharp 0.5 (g h e) endsharp\n"
    "endmesh\n"
    "instance k box endinstance\n";

// The positions of an OBJ file, sorted (the viewer and the command line may number vertices apart).
std::vector<Vec3> sorted_positions(const std::string& path) {
  const PolygonSoup soup = read_polygons(path);
  std::vector<Vec3> out(soup.positions.begin(), soup.positions.end());
  std::sort(out.begin(), out.end(), [](const Vec3& p, const Vec3& q) {
    return std::lexicographical_compare(&p.x, &p.x + 3, &q.x, &q.x + 3);
  });
  return out;
}

}  // namespace

TEST_CASE(
    "the viewer's crease method and smooth triangles change the subdivided stage as the command line's do",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("crease_settings");
  const std::string scene = dir + "/box.nome";
  std::ofstream(scene) << creased_box_text;
  viewer::ViewerOptions options;
  options.file = scene;
  options.script = nome::test::write_script(
      dir, "subdiv 3\nexport " + dir + "/uniform.obj\nsetting creases chaikin\nexport " + dir +
               "/chaikin.obj\nsetting smooth-triangles on\nexport " + dir +
               "/smooth.obj\nsetting creases uniform\nsetting smooth-triangles off\nexport " + dir +
               "/back.obj\nquit\n");
  nome::test::TestViewer viewer(options);
  REQUIRE(viewer.run() == 0);

  const auto uniform = sorted_positions(dir + "/uniform.obj");
  const auto chaikin = sorted_positions(dir + "/chaikin.obj");
  const auto smooth = sorted_positions(dir + "/smooth.obj");
  CHECK(uniform.size() == chaikin.size());
  CHECK(chaikin != uniform);
  CHECK(smooth != chaikin);
  CHECK(sorted_positions(dir + "/back.obj") == uniform);

  const auto cli = [&](const std::string& options, const std::string& out) {
    const auto r =
        nome::test::run_nome_in_process("export " + scene + " --subdiv 3 " + options + " -o " + out);
    INFO(r.err);
    REQUIRE(r.status == 0);
    return sorted_positions(out);
  };
  CHECK(cli("", dir + "/cli_uniform.obj") == uniform);
  CHECK(cli("--crease-method chaikin", dir + "/cli_chaikin.obj") == chaikin);
  CHECK(cli("--crease-method chaikin --smooth-triangles", dir + "/cli_smooth.obj") == smooth);
  CHECK_THAT(
      nome::test::run_nome_in_process("export " + scene + " --crease-method even -o " + dir + "/x.obj").err,
      Catch::StartsWith("nome export: --crease-method expects uniform or chaikin, found 'even'"));
}
