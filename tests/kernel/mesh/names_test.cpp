#include <catch2/catch.hpp>

#include <cstdint>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/names.hpp"

using nome::Names;

TEST_CASE("copies of names share one list until one of them changes it", "[kernel]") {
  const Names original(std::vector<std::string>{"v0", "v1", "v2"});
  Names copy = original;
  REQUIRE(copy.shares_with(original));
  CHECK(copy[2] == "v2");  // reading through a non-const copy keeps the list shared
  REQUIRE(copy.shares_with(original));
  REQUIRE(copy == original);

  copy.writable()[1] = "renamed";
  CHECK(!copy.shares_with(original));
  CHECK(original[1] == "v1");
  CHECK(copy[1] == "renamed");
  CHECK_FALSE(copy == original);

  Names appended = original;
  appended.append(original);
  CHECK(appended.size() == 6);
  CHECK(appended[3] == "v0");
  CHECK(original.size() == 3);
  Names doubled{"a", "b"};
  doubled.append(doubled);
  CHECK(doubled.list() == std::vector<std::string>{"a", "b", "a", "b"});
  appended.writable().erase(appended.writable().begin() + 1, appended.writable().begin() + 5);
  CHECK(std::vector<std::string>(appended.begin(), appended.end()) == std::vector<std::string>{"v0", "v2"});
}

TEST_CASE("names compare by their texts, and an empty list is no list", "[kernel]") {
  const Names a(std::vector<std::string>{"f0", "f1"});
  const Names b(std::vector<std::string>{"f0", "f1"});
  CHECK(!a.shares_with(b));
  CHECK(a == b);
  Names none;
  CHECK(none.empty());
  CHECK(none == Names(std::vector<std::string>{}));
  none.resize(2);
  CHECK(none.size() == 2);
  CHECK(none[0].empty());
  none.clear();
  CHECK(none.empty());
}

TEST_CASE("a mesh built from a soup holds the soup's names without copying them", "[kernel]") {
  nome::PolygonSoup soup;
  for (int i = 0; i < 4; ++i) soup.add_vertex(nome::Vec3(i % 2, i / 2, 0));
  soup.add_face({0, 1, 3, 2});
  soup.vertex_names = std::vector<std::string>{"a", "b", "c", "d"};
  soup.face_names = std::vector<std::string>{"square"};
  const nome::PolygonSoup kept = soup;
  const nome::Mesh mesh = nome::build_mesh(soup);
  CHECK(mesh.vertex_names().shares_with(kept.vertex_names));
  CHECK(mesh.vertex_label(3) == "d");
  CHECK(mesh.face_label(0) == "square");
}

TEST_CASE("grid names are made when read, and stay a rule through prefixes and appends", "[kernel]") {
  const std::uint64_t made = Names::lists_made();
  Names grid = Names::grid({'f', 3, 2, {"a", "b"}}, 9);  // rows 3, 4 and half of 5
  REQUIRE(grid.size() == 9);
  CHECK(grid[0] == "f3_0a");
  CHECK(grid[1] == "f3_0b");
  CHECK(grid[3] == "f3_1b");
  CHECK(grid[4] == "f4_0a");
  CHECK(grid[8] == "f5_0a");

  Names placed = grid;
  placed.add_prefix("i_");
  CHECK(placed[5] == "i_f4_0b");
  CHECK(grid[5] == "f4_0b");
  placed.append(Names{"endcap"});
  placed.resize(12);
  REQUIRE(placed.size() == 12);
  CHECK(placed[8] == "i_f5_0a");
  CHECK(placed[9] == "endcap");
  CHECK(placed[10].empty());
  placed.add_prefix("top_");
  CHECK(placed[9] == "top_endcap");
  CHECK(placed[11] == "top_");
  CHECK(Names::lists_made() == made);  // nothing so far made the whole list

  const std::vector<std::string> whole(placed.begin(), placed.end());
  CHECK(Names::lists_made() == made + 1);
  REQUIRE(whole.size() == 12);
  for (std::size_t i = 0; i < whole.size(); ++i) CHECK(whole[i] == placed[i]);
  CHECK(placed.list().size() == 12);  // made once and kept
  CHECK(Names::lists_made() == made + 1);
}

TEST_CASE("grid names compare by rule or by text, and change like lists", "[kernel]") {
  const Names a = Names::grid({'v', 0, 3}, 6);
  const Names b = Names::grid({'v', 0, 3}, 6);
  CHECK(a == b);
  CHECK_FALSE(a == Names::grid({'v', 0, 3}, 5));
  CHECK_FALSE(a == Names::grid({'v', 1, 3}, 6));
  const Names spelled{"v0_0", "v0_1", "v0_2", "v1_0", "v1_1", "v1_2"};
  CHECK(a == spelled);
  CHECK(spelled == a);

  Names changed = a;
  changed.writable()[4] = "middle";
  CHECK(changed[4] == "middle");
  CHECK(changed[5] == "v1_2");
  CHECK(a[4] == "v1_1");
  CHECK_FALSE(changed == a);

  Names list{"p", "q"};
  list.append(a);
  REQUIRE(list.size() == 8);
  CHECK(list[1] == "q");
  CHECK(list[2] == "v0_0");
  CHECK(list[7] == "v1_2");
}
