#include <catch2/catch.hpp>

#include "nome/edit/document.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/merge.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// A named grid of quads in z = 0 starting at x = x0: vertices NAME_v<i>_<j>, faces NAME_f<i>_<j>.
PolygonSoup named_grid(const std::string& name, Index nx, Index ny, double x0) {
  PolygonSoup s = test::grid(nx, ny);
  for (Index v = 0; v < s.num_vertices(); ++v) {
    s.positions[v].x += x0;
    s.vertex_names.push_back(name + "_v" + std::to_string(v % (nx + 1)) + "_" + std::to_string(v / (nx + 1)));
  }
  for (Index f = 0; f < s.num_faces(); ++f)
    s.face_names.push_back(name + "_f" + std::to_string(f % nx) + "_" + std::to_string(f / nx));
  return s;
}

// Two 2 x 2 grids with a gap of one unit between x = 2 and x = 3.
PolygonSoup two_grids() {
  return [] {
    PolygonSoup left = named_grid("left", 2, 2, 0.0), right = named_grid("right", 2, 2, 3.0);
    PolygonSoup s = test::disjoint_union(left, right);
    s.vertex_names = left.vertex_names;
    s.vertex_names.append(right.vertex_names);
    s.face_names = left.face_names;
    s.face_names.append(right.face_names);
    return s;
  }();
}

// The scene and every edited face in one mesh, sharing vertices by name.
Mesh everything(const Document& doc) {
  PolygonSoup soup = to_soup(glue_faces(doc.scene_soup()).mesh);
  auto id = [&](const std::string& name) {
    return Index(std::find(soup.vertex_names.begin(), soup.vertex_names.end(), name) -
                 soup.vertex_names.begin());
  };
  for (const auto* list : {&doc.consolidated_faces(), &doc.temporary_faces()})
    for (const EditedFace& face : *list) {
      std::vector<Index> ids;
      for (const std::string& v : face.vertices) ids.push_back(id(v));
      soup.add_face(ids);
      soup.face_names.push_back(face.name);
    }
  return build_mesh(std::move(soup));
}

}  // namespace

TEST_CASE("an added polygon takes the orientation of its neighbours", "[kernel]") {
  Document doc(two_grids());
  // Bridge the gap, listing the corners in the order that disagrees with both grids.
  const EditOutcome added = doc.add_polygon({"left_v2_0", "left_v2_1", "right_v0_1", "right_v0_0"});
  REQUIRE(added.applied);
  REQUIRE(doc.temporary_faces().size() == 1);
  CHECK(doc.temporary_faces()[0].vertices.front() == "right_v0_0");
  const TopologyReport r = topology_report(everything(doc));
  CHECK(r.mobius_edges == 0);
  CHECK(r.components.size() == 1);
}

TEST_CASE("polygons that would break the surface are refused with a reason", "[kernel]") {
  Document doc(two_grids());
  const EditOutcome repeated = doc.add_polygon({"left_v2_0", "left_v2_1", "left_v2_0"});
  CHECK_FALSE(repeated.applied);
  CHECK_THAT(repeated.message, Catch::Contains("left_v2_0"));
  // left_v1_0 - left_v1_1 is inside the left grid: it has two faces already.
  const EditOutcome third = doc.add_polygon({"left_v1_0", "left_v1_1", "right_v0_0"});
  CHECK_FALSE(third.applied);
  CHECK_THAT(third.message, Catch::Contains("two faces") && Catch::Contains("left_f0_0"));
  CHECK_FALSE(doc.add_polygon({"left_v2_0", "nowhere", "right_v0_0"}).applied);
  CHECK_FALSE(doc.add_polygon({"left_v2_0", "right_v0_0"}).applied);
  CHECK(doc.temporary_faces().empty());
  CHECK_FALSE(doc.can_undo());

  // An edge filled by an earlier added face counts too.
  REQUIRE(doc.add_polygon({"left_v2_0", "left_v2_1", "right_v0_1", "right_v0_0"}).applied);
  REQUIRE(doc.add_polygon({"left_v2_1", "left_v2_2", "right_v0_2", "right_v0_1"}).applied);
  CHECK_FALSE(doc.add_polygon({"left_v2_1", "right_v0_1", "right_v1_1"}).applied);
}

TEST_CASE("accept, clear and delete are undone and redone step by step", "[kernel]") {
  Document doc(two_grids());
  REQUIRE(doc.add_polygon({"left_v2_0", "left_v2_1", "right_v0_1", "right_v0_0"}).applied);
  REQUIRE(doc.accept_temporary().applied);
  REQUIRE(doc.add_polygon({"left_v2_1", "left_v2_2", "right_v0_2", "right_v0_1"}).applied);
  CHECK(doc.consolidated_faces().size() == 1);
  CHECK(doc.temporary_faces().size() == 1);
  REQUIRE(doc.clear_temporary().applied);
  CHECK(doc.temporary_faces().empty());
  REQUIRE(doc.delete_faces({"left_f0_0", doc.consolidated_faces()[0].name}).applied);
  CHECK(doc.consolidated_faces().empty());
  CHECK(doc.deleted_faces() == std::vector<std::string>{"left_f0_0"});

  REQUIRE(doc.undo());  // delete
  CHECK(doc.consolidated_faces().size() == 1);
  CHECK(doc.deleted_faces().empty());
  REQUIRE(doc.undo());  // clear
  CHECK(doc.temporary_faces().size() == 1);
  REQUIRE(doc.undo());  // second add
  REQUIRE(doc.undo());  // accept
  CHECK(doc.consolidated_faces().empty());
  CHECK(doc.temporary_faces().size() == 1);
  REQUIRE(doc.undo());  // first add
  CHECK(doc.temporary_faces().empty());
  CHECK_FALSE(doc.undo());

  for (int k = 0; k < 5; ++k) REQUIRE(doc.redo());
  CHECK_FALSE(doc.redo());
  CHECK(doc.consolidated_faces().empty());
  CHECK(doc.deleted_faces() == std::vector<std::string>{"left_f0_0"});

  // A new edit after undoing drops what could have been redone.
  REQUIRE(doc.undo());
  REQUIRE(doc.add_polygon({"right_v0_2", "left_v2_2", "left_v2_1", "right_v0_1"}).applied);
  CHECK_FALSE(doc.can_redo());
}

TEST_CASE("deleting faces drops the edges and vertices no face uses any more", "[kernel]") {
  Document doc(two_grids());
  CHECK(glue_faces(doc.scene_soup()).mesh.num_vertices() == 18);
  REQUIRE(doc.delete_faces({"left_f0_0"}).applied);
  const Mesh m = glue_faces(doc.scene_soup()).mesh;
  CHECK(m.num_faces() == 7);
  CHECK(m.num_vertices() == 17);  // the corner left_v0_0 is gone
  CHECK(m.num_edges() == 24 - 2);
  CHECK_FALSE(doc.delete_faces({"left_f0_0"}).applied);  // already deleted
  CHECK_FALSE(doc.delete_faces({"no_such_face"}).applied);

  // Deleting two diagonal faces leaves the centre vertex pinched: it becomes one vertex per fan.
  REQUIRE(doc.delete_faces({"left_f1_1"}).applied);
  const Mesh pinched = glue_faces(doc.scene_soup()).mesh;
  CHECK(pinched.num_vertices() == 7 + 1 + 9);
  CHECK(pinched.num_components() == 3);
}

TEST_CASE("edits follow vertex names through geometry changes and report what vanished", "[kernel]") {
  Document doc(two_grids());
  REQUIRE(doc.add_polygon({"left_v2_1", "left_v2_2", "right_v0_2", "right_v0_1"}).applied);
  REQUIRE(doc.delete_faces({"right_f1_1"}).applied);

  // A "slider" moves the right grid and lowers its size to 1 x 1: right_v0_2 and right_f1_1 vanish.
  PolygonSoup left = named_grid("left", 2, 2, 0.0), right = named_grid("right", 1, 1, 2.5);
  PolygonSoup smaller = test::disjoint_union(left, right);
  smaller.vertex_names = left.vertex_names;
  smaller.vertex_names.append(right.vertex_names);
  smaller.face_names = left.face_names;
  smaller.face_names.append(right.face_names);
  doc.set_scene_geometry(smaller);
  const std::vector<UnresolvedEdit> gone = doc.unresolved();
  REQUIRE(gone.size() == 2);
  CHECK(gone[0].face == doc.temporary_faces()[0].name);
  CHECK(gone[0].missing == std::vector<std::string>{"right_v0_2"});
  CHECK(gone[1].face == "right_f1_1");
  CHECK(glue_faces(doc.temporary_soup()).mesh.num_faces() == 0);
  CHECK(doc.temporary_faces().size() == 1);  // kept, not dropped

  doc.set_scene_geometry(two_grids());
  CHECK(doc.unresolved().empty());
  const Mesh temporary = glue_faces(doc.temporary_soup()).mesh;
  REQUIRE(temporary.num_faces() == 1);
  const auto& names = temporary.vertex_names();
  const Index back = Index(std::find(names.begin(), names.end(), "right_v0_2") - names.begin());
  REQUIRE(back < temporary.num_vertices());
  CHECK(temporary.position(back) == Vec3(3.0, 2.0, 0.0));
}

TEST_CASE("the temporary mesh may touch itself at a vertex before the face between is added", "[kernel]") {
  Document doc(two_grids());
  // Two triangles sharing only left_v2_1 (the report's example), then the one joining them.
  REQUIRE(doc.add_polygon({"left_v2_0", "left_v2_1", "right_v0_0"}).applied);
  REQUIRE(doc.add_polygon({"left_v2_1", "left_v2_2", "right_v0_2"}).applied);
  CHECK(glue_faces(doc.temporary_soup()).mesh.num_vertices() == 6);
  REQUIRE(doc.add_polygon({"left_v2_1", "right_v0_2", "right_v0_1", "right_v0_0"}).applied);
  const Mesh temporary = glue_faces(doc.temporary_soup()).mesh;
  CHECK(temporary.num_vertices() == 6);
  CHECK(temporary.num_components() == 1);
  CHECK(topology_report(temporary).mobius_edges == 0);
}

TEST_CASE("zipper adds a strip to the temporary mesh, accepted and merged it closes the gap", "[kernel]") {
  Document doc(two_grids());
  const Mesh shown = glue_faces(doc.scene_soup()).mesh;
  auto vertex = [&](const std::string& name) {
    const auto& names = shown.vertex_names();
    return Index(std::find(names.begin(), names.end(), name) - names.begin());
  };
  // The facing borders, from bottom to top: whichever way each loop runs there.
  auto along = [&](const std::string& from, const std::string& to, const std::string& second) {
    BorderSelection s{vertex(from), vertex(to), false};
    if (border_chain(shown, s)[1] != vertex(second)) s.backwards = true;
    return s;
  };
  const EditOutcome zipped = doc.zipper(shown, along("left_v2_0", "left_v2_2", "left_v2_1"),
                                        along("right_v0_0", "right_v0_2", "right_v0_1"));
  REQUIRE(zipped.applied);
  CHECK_THAT(zipped.message, Catch::Contains("2 quads and 0 triangles"));
  CHECK(doc.temporary_faces().size() == 2);
  REQUIRE(doc.accept_temporary().applied);

  const MergeResult merged = merge_boundaries(glue_faces(doc.pipeline_input().soup).mesh);
  const TopologyReport r = topology_report(merged.mesh);
  CHECK(r.faces == 10);
  CHECK(r.components.size() == 1);
  CHECK(r.chi == 1);
  CHECK(r.mobius_edges == 0);
  REQUIRE(doc.undo());
  REQUIRE(doc.undo());
  CHECK(doc.temporary_faces().empty());
}

TEST_CASE("saved edits load without history", "[kernel]") {
  Document doc(two_grids());
  doc.load_edits({{"left_v2_0", "left_v2_1", "right_v0_1", "right_v0_0"}}, {"left_f0_0"});
  CHECK(doc.consolidated_faces().size() == 1);
  CHECK(doc.deleted_faces().size() == 1);
  CHECK_FALSE(doc.can_undo());
  CHECK(doc.consolidated_soup().num_faces() == 1);
  // Loaded over edits made and undone: what could have been redone goes with the rest of the history.
  Document edited(two_grids());
  REQUIRE(edited.add_polygon({"left_v2_0", "left_v2_1", "right_v0_1", "right_v0_0"}).applied);
  REQUIRE(edited.undo());
  REQUIRE(edited.can_redo());
  edited.load_edits({}, {"left_f0_0"});
  CHECK_FALSE(edited.can_undo());
  CHECK_FALSE(edited.can_redo());
  CHECK_FALSE(edited.redo());
  CHECK(edited.temporary_faces().empty());
}

TEST_CASE("glue_faces splits vertices where faces only touch and leaves three-face edges apart", "[kernel]") {
  PolygonSoup pinch = test::grid(2, 2);
  PolygonSoup two;  // faces 1 and 2 of the grid share only the centre vertex 4
  two.positions = pinch.positions;
  two.add_face({1, 2, 5, 4});
  two.add_face({3, 4, 7, 6});
  const GluedFaces glued = glue_faces(two);
  CHECK(glued.mesh.num_vertices() == 8);
  CHECK(glued.mesh.num_components() == 2);
  CHECK(std::count(glued.vertex_sources.begin(), glued.vertex_sources.end(), 4) == 2);

  PolygonSoup book;
  book.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  book.add_face({0, 1, 2});
  book.add_face({1, 0, 3});
  book.add_face({0, 1, 4});
  const GluedFaces spine = glue_faces(book);
  REQUIRE(spine.problems.size() == 1);
  CHECK_THAT(spine.problems[0], Catch::Contains("3 faces"));
  CHECK(spine.mesh.num_faces() == 3);
}
