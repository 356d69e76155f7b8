#include <catch2/catch.hpp>

#include "support/shapes.hpp"
#include "viewer/view/selection.hpp"

using namespace nome;
using nome::viewer::Selection;
using nome::viewer::SelectionMode;

TEST_CASE("vertices and faces toggle and keep their click order", "[app]") {
  Selection s;
  s.click_vertex(4);
  s.click_vertex(1);
  s.click_vertex(7);
  CHECK(s.vertices() == std::vector<Index>{4, 1, 7});
  s.click_vertex(1);  // again: deselected
  CHECK(s.vertices() == std::vector<Index>{4, 7});
  s.set_mode(SelectionMode::face);
  s.click_face(2);
  s.click_face(2);
  CHECK(s.faces().empty());
  CHECK(s.vertices().size() == 2);  // changing the mode keeps the selection
  s.clear();
  CHECK(s.is_empty());
}

TEST_CASE("a whole border comes from one click and goes with a click on any of its vertices", "[app]") {
  const Mesh mesh = build_mesh(test::grid(3, 2));
  const BorderLookup borders(mesh);
  Selection s;
  s.set_mode(SelectionMode::border);
  CHECK_FALSE(s.click_border_vertex(borders, 5).empty());  // interior: refused with a hint
  CHECK(s.borders().empty());
  CHECK(s.click_border_vertex(borders, 3).empty());
  REQUIRE(s.borders().size() == 1);
  CHECK(s.borders()[0].is_loop);
  CHECK(s.borders()[0].vertices.size() == 10);
  CHECK(s.borders()[0].vertices.front() == 3);  // the zipper's matching point
  s.click_border_vertex(borders, 8);
  CHECK(s.borders().empty());
}

TEST_CASE("a partial border takes two ends and a side, or two neighbouring ends", "[app]") {
  const Mesh mesh = build_mesh(test::grid(3, 2));
  const BorderLookup borders(mesh);
  const auto loop = borders.whole_loop_from(0);
  Selection s;
  s.set_mode(SelectionMode::border_partial);
  CHECK_FALSE(s.click_border_vertex(borders, loop[0]).empty());  // "pick the other end"
  CHECK_FALSE(s.click_border_vertex(borders, loop[3]).empty());  // "pick a side"
  CHECK(s.click_border_vertex(borders, loop[6]).empty());
  REQUIRE(s.borders().size() == 1);
  CHECK_FALSE(s.borders()[0].is_loop);
  CHECK(s.borders()[0].vertices.size() == 8);
  CHECK(s.pending_ends().empty());

  s.click_border_vertex(borders, loop[5]);  // on the selected segment: deselects it
  CHECK(s.borders().empty());

  s.click_border_vertex(borders, loop[1]);
  CHECK(s.click_border_vertex(borders, loop[2]).empty());  // neighbours: done without a side
  REQUIRE(s.borders().size() == 1);
  CHECK(s.borders()[0].vertices == std::vector<Index>{loop[1], loop[2]});
}
