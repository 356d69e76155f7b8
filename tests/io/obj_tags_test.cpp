#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "nome/error.hpp"
#include "nome/io/obj.hpp"
#include "nome/io/obj_tags.hpp"
#include "support/scratch_files.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

fs::path write_tagged_obj(const std::string& name, const std::string& text) {
  const fs::path path = test::scratch_path("nome_obj_tags_tests", name);
  std::ofstream(path) << text;
  return path;
}

// Two quads side by side: vertices 0..5, faces 0 and 1 sharing the edge 1-4.
const std::string two_quads_obj =
    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n";

}  // namespace

TEST_CASE("OpenSubdiv's OBJ tags become crease and corner weights, holes and options", "[io]") {
  const fs::path p =
      write_tagged_obj("tagged.obj", two_quads_obj +
                                         "t crease 2/1/0 1 4 2.5\nt corner 1/1/0 0 10\nt hole 1/0/0 1\n"
                                         "t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\n"
                                         "t smoothtriangles 0/0/1 smooth\n"
                                         "t vertexedit 1/0/1 0 add\nt vertexedit 1/0/1 1 add\n");
  const Mesh m = build_mesh(read_obj(p));
  Index shared = no_index;
  for (Index e = 0; e < m.num_edges(); ++e)
    if (!m.edge(e).is_boundary()) shared = e;
  REQUIRE(shared != no_index);
  CHECK(m.edge_sharpness(shared) == 2.5f);
  CHECK_FALSE(m.edge(shared).is_sharp);
  CHECK(m.vertex_sharpness(0) == infinite_sharpness);
  CHECK_FALSE(m.is_hole(0));
  CHECK(m.is_hole(1));
  const ObjSubdivisionTags tags = read_obj_subdivision_tags(p);
  CHECK(tags.boundary == BoundaryMode::edge_and_corner);
  CHECK(tags.crease_method == CreaseMethod::chaikin);
  CHECK(tags.smooth_triangles == true);
  REQUIRE(tags.notes.size() == 1);  // one note per kind of tag not applied
  CHECK_THAT(tags.notes[0], Catch::Contains(":15: 't vertexedit' ignored"));

  // Written back with the mesh, they read back the same.
  const fs::path again = write_tagged_obj("again.obj", "");
  write_obj(again, m, tags);
  const Mesh back = build_mesh(read_obj(again));
  CHECK(back.edge_sharpness_weights() == m.edge_sharpness_weights());
  CHECK(back.vertex_sharpness_weights() == m.vertex_sharpness_weights());
  CHECK(back.face_holes() == m.face_holes());
  ObjSubdivisionTags expected = tags;
  expected.notes.clear();
  CHECK(read_obj_subdivision_tags(again) == expected);
}

TEST_CASE("bad OBJ tags name the file, line and column", "[io]") {
  CHECK_THROWS_WITH(read_obj(write_tagged_obj("count.obj", two_quads_obj + "t crease 2/1/0 1 4\n")),
                    Catch::Contains("count.obj:9:1: 't crease' announces 3 values, found 2"));
  CHECK_THROWS_WITH(read_obj(write_tagged_obj("word.obj", two_quads_obj + "t crease 2/1/0 1 x 2\n")),
                    Catch::Contains("word.obj:9:18: expected a whole number, found 'x'"));
  CHECK_THROWS_WITH(read_obj(write_tagged_obj("range.obj", two_quads_obj + "t corner 1/1/0 6 1\n")),
                    Catch::Contains("range.obj:9: 't corner' names vertex 6, the file has 6"));
  CHECK_THROWS_WITH(read_obj(write_tagged_obj("spec.obj", two_quads_obj + "t hole one 1\n")),
                    Catch::Contains("spec.obj:9:8: expected the counts"));
  CHECK_THROWS_AS(
      build_mesh(read_obj(write_tagged_obj("edge.obj", two_quads_obj + "t crease 2/1/0 0 5 1\n"))),
      TopologyError);
}
