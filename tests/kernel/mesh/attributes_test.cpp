#include <catch2/catch.hpp>

#include <cstdint>

#include "nome/error.hpp"
#include "nome/mesh/attributes.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/mesh/input_faces.hpp"
#include "nome/mesh/mesh.hpp"
#include "support/shapes.hpp"

using namespace nome;

TEST_CASE("an attribute is found by its name and type, with its fallback past its values", "[kernel]") {
  Attributes faces;
  CHECK(faces.empty());
  Column<std::int32_t>& material = faces.add<std::int32_t>("material", -1);
  material.set(2, 7);
  CHECK(material.size() == 3);
  CHECK(material[0] == -1);
  CHECK(material[2] == 7);
  CHECK(material[100] == -1);
  // Asked again, the same column; asked with another type, none, and adding it so is refused.
  CHECK(&faces.add<std::int32_t>("material", 0) == &material);
  CHECK(faces.find<float>("material") == nullptr);
  CHECK_THROWS_AS(faces.add<float>("material", 0.0f), InvalidInputError);
  CHECK(std::as_const(faces).find<std::int32_t>("region") == nullptr);
  faces.remove("material");
  CHECK(faces.empty());
}

TEST_CASE("copies share an attribute's values until one of them writes", "[kernel]") {
  Attributes a;
  a.add<float>("weight", 0.0f).set(0, 1.5f);
  Attributes b = a;
  CHECK(b == a);
  CHECK(std::as_const(b).find<float>("weight") == std::as_const(a).find<float>("weight"));
  b.find<float>("weight")->set(0, 2.5f);
  CHECK((*std::as_const(a).find<float>("weight"))[0] == 1.5f);
  CHECK((*std::as_const(b).find<float>("weight"))[0] == 2.5f);
  CHECK_FALSE(b == a);
  // Writing back the same value makes them equal again though they no longer share.
  b.find<float>("weight")->set(0, 1.5f);
  CHECK(b == a);
}

TEST_CASE("appending attributes fills the side that had none with the fallback", "[kernel]") {
  Attributes into;
  into.add<std::int32_t>("material", -1).set(0, 3);
  Attributes part;
  part.add<Color>("color", no_face_color).set(1, Color(1, 0, 0));
  into.append(part, 2);  // `into` described 2 elements, `part` 2 more
  const Column<std::int32_t>* material = std::as_const(into).find<std::int32_t>("material");
  const Column<Color>* color = std::as_const(into).find<Color>("color");
  REQUIRE(material);
  REQUIRE(color);
  CHECK(std::vector<std::int32_t>{(*material)[0], (*material)[1], (*material)[2], (*material)[3]} ==
        std::vector<std::int32_t>{3, -1, -1, -1});
  CHECK((*color)[0] == no_face_color);
  CHECK((*color)[2] == no_face_color);
  CHECK((*color)[3] == Color(1, 0, 0));
  Attributes other;
  other.add<float>("material", 0.0f).set(0, 1.0f);
  CHECK_THROWS_AS(into.append(other, 4), InvalidInputError);
}

TEST_CASE("carried attributes follow each element's parent; a dropped one ends there", "[kernel]") {
  Attributes input;
  Column<std::int32_t>& material = input.add<std::int32_t>("material", -1);
  for (Index f = 0; f < 3; ++f) material.set(f, std::int32_t(10 * f));
  input.add<std::int32_t>("scratch", 0, AttributeRule::drop).set(0, 1);
  const Attributes out = carried(input, std::vector<Index>{2, 2, 0, no_index, 1});
  CHECK(out.find<std::int32_t>("scratch") == nullptr);
  const Column<std::int32_t>* m = out.find<std::int32_t>("material");
  REQUIRE(m);
  CHECK(m->values() == std::vector<std::int32_t>{20, 20, 0, -1, 10});
  const Attributes same = carried(input, ElementOrigins::identity());
  CHECK(same.find<std::int32_t>("scratch") == nullptr);
  CHECK(same.find<std::int32_t>("material")->values() == material.values());
}

TEST_CASE("a mesh built from a soup keeps its face attributes, and to_soup gives them back", "[kernel]") {
  PolygonSoup soup = test::mobius_band(6, 1);
  mark_input_faces(soup);
  add_colors(soup.face_attributes).set(3, Color(0, 1, 0));
  const Mesh mesh = build_mesh(soup);
  for (Index f = 0; f < mesh.num_faces(); ++f) CHECK(input_face(mesh, f) == f);
  CHECK(face_color(mesh.face_attributes(), 3) == Color(0, 1, 0));
  CHECK(face_color(mesh.face_attributes(), 2) == no_face_color);
  CHECK_FALSE(input_face(mesh, mesh.num_faces()));
  CHECK(to_soup(mesh).face_attributes == soup.face_attributes);
  // More values than faces is refused.
  soup.face_attributes.add<std::int32_t>("material", 0).set(soup.num_faces(), 1);
  CHECK_THROWS_AS(build_mesh(soup), InvalidInputError);
}
