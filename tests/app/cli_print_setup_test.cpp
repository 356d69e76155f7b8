#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/cli_support.hpp"
#include "nome/io/stl.hpp"

using nome::test::run_nome_in_process;

namespace {

// A 6 x 4 x 1 box, turned so that no side starts out level, faces oriented outward.
std::string tilted_box_obj() {
  glm::dmat4 m = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 0.5)));
  m = glm::scale(m, glm::dvec3(3.0, 2.0, 0.5));
  std::ostringstream obj;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 p = m * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1.0);
    obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  }
  obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return obj.str();
}

struct StlFigures {
  double low_z = 1e300, high_z = -1e300;
  double area_down = 0.0;  // of the triangles lying in z = low_z, wound to face -z
};

StlFigures stl_figures(const std::string& path) {
  const nome::PolygonSoup soup = nome::read_stl(path);
  StlFigures out;
  for (const nome::Vec3& p : soup.positions) {
    out.low_z = std::min(out.low_z, p.z);
    out.high_z = std::max(out.high_z, p.z);
  }
  for (nome::Index f = 0; f < soup.num_faces(); ++f) {
    const nome::Index* vs = soup.face_vertices.data() + soup.face_offsets[f];
    const nome::Vec3 a = soup.positions[vs[0]], b = soup.positions[vs[1]], c = soup.positions[vs[2]];
    const bool is_low =
        std::abs(a.z - out.low_z) + std::abs(b.z - out.low_z) + std::abs(c.z - out.low_z) < 1e-3;
    const nome::Vec3 n = glm::cross(b - a, c - a);
    if (is_low && n.z < 0) out.area_down += 0.5 * glm::length(n);
  }
  return out;
}

}  // namespace

TEST_CASE("nome export --fit-height 60mm --rest-on flattest stands the solid 60 mm tall on z = 0", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("print_setup");
  std::ofstream(dir + "/box.obj") << tilted_box_obj();
  const auto r = run_nome_in_process("export " + dir + "/box.obj -o " + dir +
                                     "/box.stl --fit-height 60mm "
                                     "--rest-on flattest --no-check");
  REQUIRE(r.status == 0);
  const StlFigures placed = stl_figures(dir + "/box.stl");
  CHECK(placed.low_z == Approx(0.0).margin(1e-4));
  CHECK(placed.high_z == Approx(60.0).epsilon(1e-6));
  // It stands on a 6 x 4 side, now 360 x 240 mm, facing down.
  CHECK(placed.area_down == Approx(360.0 * 240.0).epsilon(1e-4));  // STL stores floats

  const auto inches = run_nome_in_process("export " + dir + "/box.obj -o " + dir +
                                          "/in.stl --fit-size 2in "
                                          "--rest-on 4 --no-check");
  REQUIRE(inches.status == 0);
  const StlFigures standing = stl_figures(dir + "/in.stl");
  CHECK(standing.high_z - standing.low_z == Approx(50.8).epsilon(1e-6));  // on its 4 x 1 end: 6 is the height
  CHECK(standing.area_down == Approx(50.8 * 50.8 * 4.0 / 36.0).epsilon(1e-4));
}

// Placed but not scaled: the STL is written from the placed mesh as it is, in the model's own units.
TEST_CASE("nome export --rest-on flattest alone lays the solid down at its own size", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("print_rest_only");
  std::ofstream(dir + "/box.obj") << tilted_box_obj();
  REQUIRE(
      run_nome_in_process("export " + dir + "/box.obj -o " + dir + "/rest.stl --rest-on flattest --no-check")
          .status == 0);
  const StlFigures placed = stl_figures(dir + "/rest.stl");
  CHECK(placed.low_z == Approx(0.0).margin(1e-5));
  CHECK(placed.high_z == Approx(1.0).epsilon(1e-5));  // the box's thickness
  CHECK(placed.area_down == Approx(6.0 * 4.0).epsilon(1e-4));
}

TEST_CASE("A scene keeps its print preparation and nome export applies it", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("print_setup_scene");
  std::ofstream(dir + "/band.nome") << "mobiusstrip band (1 1 2 24) endmobiusstrip\n"
                                       "instance strip band endinstance\n";
  REQUIRE(run_nome_in_process("export " + dir + "/band.nome -o " + dir +
                              "/kept.nome --fit-height 6cm "
                              "--rest-on flattest")
              .status == 0);
  std::ifstream in(dir + "/kept.nome");
  const std::string saved((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(saved, Catch::Contains("printsetup fitheight 60 reston flattest endprintsetup"));
  REQUIRE(run_nome_in_process("export " + dir + "/kept.nome --offset 0.05 -o " + dir + "/kept.stl --no-check")
              .status == 0);
  const StlFigures placed = stl_figures(dir + "/kept.stl");
  CHECK(placed.low_z == Approx(0.0).margin(1e-4));
  CHECK(placed.high_z == Approx(60.0).epsilon(1e-6));
}

TEST_CASE("Print preparation options refuse what they cannot use", "[app]") {
  const std::string file = nome::test::assets + "cube.obj";
  CHECK(run_nome_in_process("export " + file + " -o /dev/null/x.stl --fit-height 60furlongs").status == 2);
  CHECK(run_nome_in_process("export " + file + " -o /dev/null/x.stl --rest-on lowest").status == 2);
  CHECK(run_nome_in_process("export " + file + " -o /dev/null/x.stl --fit-height 6 --fit-size 6").status ==
        2);
  CHECK(run_nome_in_process("export " + file + " -o /dev/null/x.stl --fit-height 6 --scale 2").status == 2);
  const auto r = run_nome_in_process("export " + file + " -o /dev/null/x.stl --rest-on 99");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("print_placement: no face 99"));
}
