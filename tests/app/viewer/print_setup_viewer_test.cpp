#include <catch2/catch.hpp>

#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/error.hpp"
#include "nome/io/stl.hpp"
#include "viewer/session/session.hpp"

using namespace nome;

namespace {
const char* const viewer_print_band =
    "mobiusstrip band (1 1 2 24) endmobiusstrip\n"
    "instance strip band endinstance\n";
}

TEST_CASE("the viewer keeps a print preparation with the scene and its export applies it", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_print_setup");
  std::ofstream(dir + "/band.nome") << viewer_print_band;
  viewer::Session session = viewer::Session::open(dir + "/band.nome");
  session.set_print_setup(
      PrintPlacementOptions{.fit = FitTarget::height, .fit_size = 40.0, .rest = RestOn::flattest});
  CHECK(session.is_modified());
  session.save(dir + "/kept.nome");
  std::ifstream in(dir + "/kept.nome");
  const std::string saved((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(saved, Catch::Contains("printsetup fitheight 40 reston flattest endprintsetup"));

  std::ofstream(dir + "/script.txt") << "offset 0.05\nexport " << dir << "/kept.stl\nquit\n";
  const auto r = nome::test::run_window(dir + "/kept.nome --script " + dir + "/script.txt");
  REQUIRE(r.status == 0);
  const PolygonSoup stl = read_stl(dir + "/kept.stl");
  double low = 1e300, high = -1e300;
  for (const Vec3& p : stl.positions) low = std::min(low, p.z), high = std::max(high, p.z);
  CHECK(low == Approx(0.0).margin(1e-4));
  CHECK(high == Approx(40.0).epsilon(1e-6));

  viewer::Session flat = viewer::Session::open(std::string(NOME_SOURCE_DIR) + "/assets/cube.obj");
  CHECK_THROWS_AS(flat.set_print_setup(PrintPlacementOptions{.rest = RestOn::flattest}), InvalidInputError);
}
