#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>

#include "nome/error.hpp"
#include "nome/io/gltf.hpp"
#include "nome/io/ply.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/query/display_triangles.hpp"
#include "support/face_colors.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;
using namespace nome::test;
namespace fs = std::filesystem;

namespace {

// A Möbius band whose faces take three colours in turn (one-sided: the vertices show both sides).
Mesh coloured_band() {
  PolygonSoup soup = mobius_band(24, 2);
  const Color colors[] = {{1.0f, 0.2f, 0.1f}, {0.1f, 0.6f, 0.3f}, {0.2f, 0.3f, 0.9f}};
  for (Index f = 0; f < soup.num_faces(); ++f)
    add_colors(soup.face_attributes).values().push_back(colors[f % 3]);
  return build_mesh(soup);
}

// How many triangles (or faces) carry each colour.
std::map<std::array<float, 3>, int> colour_counts(const std::vector<Color>& colors) {
  std::map<std::array<float, 3>, int> counts;
  for (const Color& c : colors) ++counts[{c.r, c.g, c.b}];
  return counts;
}

}  // namespace

TEST_CASE("A .glb reads back with the same vertices, triangles, topology and colours", "[io]") {
  const Mesh band = coloured_band();
  const fs::path path = test::scratch_path("nome_coloured_io", "band.glb");
  write_glb(path, band);
  const PolygonSoup back = read_polygons(path);
  const DisplayTriangles triangles = display_triangles(band);
  CHECK(back.num_vertices() == band.num_vertices());
  CHECK(back.num_faces() == triangles.size());
  std::vector<Color> triangle_colors;
  for (Index f : triangles.faces) triangle_colors.push_back(test::face_colors(band)[f]);
  CHECK(colour_counts(test::face_colors(back)) == colour_counts(triangle_colors));
  const TopologyReport report = topology_report(build_mesh(back));
  CHECK(report.chi == 0);
  CHECK_FALSE(report.orientable);
  CHECK(report.borders == 1);
}

TEST_CASE("A .ply keeps the polygons and reads its vertex colours back onto the faces", "[io]") {
  const Mesh band = coloured_band();
  const fs::path path = test::scratch_path("nome_coloured_io", "band.ply");
  write_ply(path, band);
  const PolygonSoup back = read_polygons(path);
  REQUIRE(back.num_faces() == band.num_faces());
  CHECK(back.num_vertices() == band.num_vertices());
  REQUIRE(test::face_colors(back).size() == test::face_colors(band).size());
  for (Index f = 0; f < band.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      CHECK(test::face_colors(back)[f][k] == Approx(test::face_colors(band)[f][k]).margin(1.0 / 255));
  CHECK(topology_report(build_mesh(back)).chi == 0);
}

TEST_CASE("An ascii PLY without colours reads, a broken one is refused with its line", "[io]") {
  const fs::path good = test::scratch_path("nome_coloured_io", "square.ply");
  std::ofstream(good)
      << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const PolygonSoup square = read_polygons(good);
  CHECK(square.num_vertices() == 4);
  CHECK(square.num_faces() == 1);
  CHECK(test::face_colors(square).empty());
  const fs::path bad = test::scratch_path("nome_coloured_io", "bad.ply");
  std::ofstream(bad) << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float\nend_header\n0\n";
  CHECK_THROWS_WITH(read_polygons(bad), Catch::Contains("bad.ply:4: expected property TYPE NAME"));
  const fs::path past = test::scratch_path("nome_coloured_io", "past.ply");
  std::ofstream(past)
      << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n3 0 1 2\n";
  CHECK_THROWS_AS(read_polygons(past), IoError);
  std::ofstream(test::scratch_path("nome_coloured_io", "junk.glb")) << "not a gltf";
  CHECK_THROWS_AS(read_polygons(test::scratch_path("nome_coloured_io", "junk.glb")), IoError);
}
