#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/mesh/topology_report.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

fs::path write_text(const std::string& name, const std::string& text) {
  const fs::path p = test::scratch_path("nome_io_tests", name);
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST_CASE("OBJ write then read is exact", "[io]") {
  const Mesh m = build_mesh(test::klein_bottle(9, 7));
  const fs::path p = test::scratch_path("nome_io_tests", "klein.obj");
  write_obj(p, m);
  const Mesh back = build_mesh(read_obj(p));
  CHECK(back.positions() == m.positions());
  CHECK(back.corner_vertices() == m.corner_vertices());
  CHECK(back.face_offsets() == m.face_offsets());
}

TEST_CASE("OBJ polygons stay polygons", "[io]") {
  const fs::path p = write_text("pent.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 1.5 0\nv 0 1 0\nf 1 2 3 4 5\n");
  const PolygonSoup s = read_obj(p);
  CHECK(s.num_faces() == 1);
  CHECK(s.face_offsets[1] == 5);
}

TEST_CASE("OBJ errors name the file, line and column", "[io]") {
  const fs::path range = write_text("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n");
  CHECK_THROWS_WITH(read_obj(range), Catch::Contains("range.obj:5:7: vertex index out of range"));
  const fs::path degenerate = write_text("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  CHECK_THROWS_WITH(read_obj(degenerate),
                    Catch::Contains("two.obj:3:1: expected a face with at least 3 vertices"));
  const fs::path zero = write_text("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  CHECK_THROWS_AS(read_obj(zero), IoError);
  CHECK_THROWS_AS(read_obj(test::scratch_path("nome_io_tests", "missing.obj")), IoError);
}

TEST_CASE("STL round trips, binary and ASCII, weld back into a closed surface", "[io]") {
  const Mesh m = build_mesh(test::torus(10, 6));
  for (StlFormat format : {StlFormat::binary, StlFormat::ascii}) {
    const fs::path p =
        test::scratch_path("nome_io_tests", format == StlFormat::binary ? "torus_b.stl" : "torus_a.stl");
    write_stl(p, m, format);
    const Mesh back = build_mesh(read_stl(p));
    const TopologyReport r = topology_report(back);
    CHECK(back.num_faces() == 2 * m.num_faces());
    CHECK(back.num_vertices() == m.num_vertices());
    CHECK(r.chi == 0);
    CHECK(r.borders == 0);
    CHECK(r.mobius_edges == 0);
  }
  CHECK(fs::file_size(test::scratch_path("nome_io_tests", "torus_b.stl")) == 84 + 50 * 2 * m.num_faces());
}

TEST_CASE("a failed write leaves no file and the old content intact", "[io]") {
  const fs::path p = test::scratch_path("nome_io_tests", "keep.obj");
  write_obj(p, build_mesh(test::cube()));
  const auto before = fs::file_size(p);
  CHECK_THROWS(
      write_obj(test::scratch_path("nome_io_tests", "no_such_dir") / "x.obj", build_mesh(test::cube())));
  CHECK_FALSE(fs::exists(test::scratch_path("nome_io_tests", "no_such_dir") / "x.obj"));
  CHECK(fs::file_size(p) == before);
  for (const auto& entry : fs::directory_iterator(p.parent_path())) CHECK(entry.path().extension() != ".tmp");
}
