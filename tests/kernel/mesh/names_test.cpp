#include <catch2/catch.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/names.hpp"

using nome::Names;

TEST_CASE("copies of names share one list until one of them changes it", "[kernel]") {
  const Names original(std::vector<std::string>{"v0", "v1", "v2"});
  Names copy = original;
  REQUIRE(&copy.list() == &original.list());
  CHECK(copy[2] == "v2");  // reading through a non-const copy keeps the list shared
  REQUIRE(&copy.list() == &original.list());
  REQUIRE(copy == original);

  copy.writable()[1] = "renamed";
  CHECK(&copy.list() != &original.list());
  CHECK(original[1] == "v1");
  CHECK(copy[1] == "renamed");
  CHECK_FALSE(copy == original);

  Names appended = original;
  appended.append(original.begin(), original.end());
  CHECK(appended.size() == 6);
  CHECK(appended[3] == "v0");
  CHECK(original.size() == 3);
  appended.writable().erase(appended.writable().begin() + 1, appended.writable().begin() + 5);
  CHECK(std::vector<std::string>(appended.begin(), appended.end()) == std::vector<std::string>{"v0", "v2"});
}

TEST_CASE("names compare by their texts, and an empty list is no list", "[kernel]") {
  const Names a(std::vector<std::string>{"f0", "f1"});
  const Names b(std::vector<std::string>{"f0", "f1"});
  CHECK(&a.list() != &b.list());
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
  CHECK(&mesh.vertex_names().list() == &kept.vertex_names.list());
  CHECK(mesh.vertex_label(3) == "d");
  CHECK(mesh.face_label(0) == "square");
}
