#include <unistd.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "nome/io/obj.hpp"
#include "nome/io/stl.hpp"
#include "nome/ops/pipeline.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

PipelineSettings streamed_settings(int levels, double distance = 0.0, int after = 0) {
  PipelineSettings s;
  s.subdivision_levels = levels;
  s.offset_distance = distance;
  s.subdivision_after = after;
  return s;
}

// Writes `ext` once from the pipeline's Mesh and once from run_surface's quads or solid (a pipeline
// each) and returns both.
std::pair<std::string, std::string> both_ways(const Mesh& mesh, const PipelineSettings& s,
                                              const std::string& ext, StlFormat format = StlFormat::binary) {
  const fs::path from_mesh = test::scratch_path("nome_streamed_tests", "mesh" + ext),
                 from_quads = test::scratch_path("nome_streamed_tests", "quads" + ext);
  Pipeline whole;
  if (ext == ".obj")
    write_obj(from_mesh, whole.run(mesh, s));
  else
    write_stl(from_mesh, whole.run(mesh, s), format);
  Pipeline streamed;
  streamed.set_input(mesh);
  const PipelineSurface surface = streamed.run_surface(s, ext == ".obj");
  REQUIRE(bool(surface.quads) != bool(surface.solid));
  CHECK_FALSE(surface.mesh);
  if (surface.quads && ext == ".obj")
    write_obj(from_quads, *surface.quads);
  else if (surface.quads)
    write_stl(from_quads, *surface.quads, format);
  else if (ext == ".obj")
    write_obj(from_quads, *surface.solid);
  else
    write_stl(from_quads, *surface.solid, format);
  return {test::file_bytes(from_mesh), test::file_bytes(from_quads)};
}

}  // namespace

TEST_CASE("STL and OBJ from the last level's quads are the bytes of the Mesh's", "[io]") {
  const Mesh torus = build_mesh(test::torus(8, 4));
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  for (const Mesh* mesh : {&torus, &band})
    for (int levels : {1, 2, 3}) {
      CAPTURE(mesh->num_faces(), levels);
      for (const char* ext : {".stl", ".obj"}) {
        const auto [expected, streamed] = both_ways(*mesh, streamed_settings(levels), ext);
        CHECK(expected.size() > 84);
        CHECK(expected == streamed);
      }
      const auto [ascii, streamed_ascii] =
          both_ways(*mesh, streamed_settings(levels), ".stl", StlFormat::ascii);
      CHECK(ascii == streamed_ascii);
    }
  // The last subdivision after the offset: a Möbius band's solid (a torus) rounded.
  for (const char* ext : {".stl", ".obj"}) {
    const auto [expected, streamed] = both_ways(band, streamed_settings(1, 0.05, 2), ext);
    CHECK(expected == streamed);
  }
}

TEST_CASE("OBJ positions are written as printf's %.17g", "[io]") {
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  const fs::path p = test::scratch_path("nome_streamed_tests", "band.obj");
  write_obj(p, band);
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);  // the comment
  for (Index v = 0; v < band.num_vertices(); ++v) {
    std::getline(in, line);
    char expected[96];
    const Vec3& q = band.position(v);
    std::snprintf(expected, sizeof expected, "v %.17g %.17g %.17g", q.x, q.y, q.z);
    REQUIRE(line == expected);
  }
  std::string face = "f";
  for (Index v : band.face_vertices(0)) face += " " + std::to_string(v + 1);
  std::getline(in, line);
  CHECK(line == face);
}

TEST_CASE("run_surface gives the Mesh where the quads cannot stand for it", "[io]") {
  Mesh band = build_mesh(test::mobius_band(12, 2));
  Pipeline pipeline;
  pipeline.set_input(band);
  PipelineSettings none = streamed_settings(2);
  none.boundary = BoundaryMode::none;  // drops the faces at the border
  const PipelineSurface dropped = pipeline.run_surface(none);
  CHECK_FALSE(dropped.quads);
  REQUIRE(dropped.mesh);
  CHECK(dropped.mesh->num_faces() < 4 * 4 * band.num_faces());
  // Sharp edges: an OBJ writes them as tags, an STL has none to write.
  band.set_sharp(0, true);
  pipeline.set_input(band);
  CHECK_FALSE(pipeline.run_surface(streamed_settings(2), true).quads);
  CHECK(pipeline.run_surface(streamed_settings(2), false).quads);
  // The offset last: streamed, unless an OBJ would tag the sharp edges its Mesh copies.
  const PipelineSurface offset = pipeline.run_surface(streamed_settings(0, 0.05));
  CHECK_FALSE(offset.quads);
  CHECK_FALSE(offset.mesh);
  REQUIRE(offset.solid);
  CHECK(offset.solid->num_faces() == pipeline.run(streamed_settings(0, 0.05)).num_faces());
  const PipelineSurface tagged = pipeline.run_surface(streamed_settings(0, 0.05), true);
  CHECK_FALSE(tagged.solid);
  REQUIRE(tagged.mesh);
  CHECK(tagged.mesh->edge(0).is_sharp);
}

TEST_CASE("STL and OBJ of the offset computed as it is written are the bytes of its Mesh's", "[io]") {
  const Mesh torus = build_mesh(test::torus(8, 4));
  const Mesh band = build_mesh(test::mobius_band(12, 2));
  // Triangles and a pentagon: the polygons' own corner layout, not the quads'.
  PolygonSoup mixed;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, 1, 0), Vec3(0.5, 1.6, 0), Vec3(-0.5, 1, 0),
                        Vec3(0.5, -1, 0.2)})
    mixed.add_vertex(p);
  mixed.add_face({0, 1, 2, 3, 4});
  mixed.add_face({1, 0, 5});
  mixed.add_vertex({3.0, 3.0, 3.0});  // without faces: the solid has no vertices for it
  for (const Mesh& mesh : {torus, band, build_mesh(mixed)})
    for (int levels : {0, 1}) {
      CAPTURE(mesh.num_faces(), levels);
      for (const char* ext : {".stl", ".obj"}) {
        const auto [expected, streamed] = both_ways(mesh, streamed_settings(levels, 0.05), ext);
        CHECK(expected.size() > 84);
        CHECK(expected == streamed);
      }
      const auto [ascii, streamed_ascii] =
          both_ways(mesh, streamed_settings(levels, 0.05), ".stl", StlFormat::ascii);
      CHECK(ascii == streamed_ascii);
    }
}

TEST_CASE("after a streamed offset the subdivision stays cached, and moved vertices rebuild it", "[io]") {
  const Mesh torus = build_mesh(test::torus(8, 4));
  Pipeline pipeline;
  pipeline.set_input(torus);
  REQUIRE(pipeline.run_surface(streamed_settings(2, 0.05)).solid);
  // What `nome export` then runs for the print check: the surface under the offset.
  PipelineSettings surface = streamed_settings(2);
  surface.stage = Stage::subdivided;
  CHECK(pipeline.run(surface).positions() == Pipeline().run(torus, surface).positions());
  CHECK(pipeline.work(Stage::subdivided) == StageWork::cached);
  Mesh moved = torus;
  moved.positions()[0] += Vec3(0.1, 0.0, 0.0);
  pipeline.set_input(moved);
  CHECK(pipeline.run(surface).positions() == Pipeline().run(moved, surface).positions());
  CHECK(pipeline.work(Stage::subdivided) == StageWork::rebuilt);
  pipeline.set_input(torus);
  CHECK(pipeline.run(surface).positions() == Pipeline().run(torus, surface).positions());
  CHECK(pipeline.work(Stage::subdivided) == StageWork::positions);
}
