// OBJ, STL (ASCII and binary), SIF, SLF and .nome text read by tiny parsers in the test, and readers fed
// files written here whose meaning is known: exact coordinates, 1-based indices in winding order, facet
// normals by the right-hand rule, shells and instances numbered and placed as written.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/io/obj.hpp"
#include "nome/io/obj_tags.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/io/sif.hpp"
#include "nome/io/stl.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"
#include "support/scratch_files.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

fs::path tfo_write(const std::string& name, const std::string& text) {
  const fs::path path = test::scratch_path("nome_text_formats", name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::vector<std::string> tfo_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// A pentagon and a quad sharing an edge, each planar but tilted, with coordinates that need all 17 digits.
PolygonSoup tfo_polygons() {
  PolygonSoup soup;
  const double third = 1.0 / 3.0;
  for (const Vec3& p : {Vec3(0.1, 0, 0), Vec3(2, 0, 0), Vec3(2.5, 1, 1), Vec3(1, 2, 2), Vec3(-0.5, 1, 1),
                        Vec3(third, -2, -2 * third), Vec3(2.0000001, -2, -2 * third)})
    soup.add_vertex(p);
  soup.add_face({0, 1, 2, 3, 4});
  soup.add_face({0, 5, 6, 1});
  return soup;
}

}  // namespace

TEST_CASE("an OBJ holds every position to the last bit and each face's 1-based indices in winding order",
          "[io]") {
  const PolygonSoup soup = tfo_polygons();
  Mesh mesh = build_mesh(soup);
  Index shared = no_index;  // the edge 0-1 the faces share
  for (Index e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edge(e).is_boundary()) shared = e;
  REQUIRE(shared != no_index);
  mesh.set_edge_sharpness(shared, 2.5f);
  mesh.set_vertex_sharpness(3, 1.5f);
  mesh.set_hole(1, true);
  const fs::path path = test::scratch_path("nome_text_formats", "two.obj");
  ObjSubdivisionTags tags;
  tags.boundary = BoundaryMode::edge_and_corner;
  tags.crease_method = CreaseMethod::chaikin;
  write_obj(path, mesh, tags);
  std::vector<Vec3> positions;
  std::vector<std::vector<long>> faces;
  std::vector<std::string> tag_lines;
  std::istringstream in(test::file_bytes(path));
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> w = tfo_words(line);
    if (w.empty() || w[0] == "#") continue;
    if (w[0] == "v") {
      REQUIRE(w.size() == 4);
      positions.emplace_back(std::strtod(w[1].c_str(), nullptr), std::strtod(w[2].c_str(), nullptr),
                             std::strtod(w[3].c_str(), nullptr));
    } else if (w[0] == "f") {
      faces.emplace_back();
      for (std::size_t k = 1; k < w.size(); ++k)
        faces.back().push_back(std::strtol(w[k].c_str(), nullptr, 10));
    } else {
      tag_lines.push_back(line);
    }
  }
  CHECK(positions == std::vector<Vec3>(soup.positions.begin(), soup.positions.end()));
  CHECK(faces == std::vector<std::vector<long>>{{1, 2, 3, 4, 5}, {1, 6, 7, 2}});
  const std::vector<std::string> expected_either[] = {
      {"t interpolateboundary 1/0/0 1", "t creasemethod 0/0/1 chaikin", "t crease 2/1/0 0 1 2.5",
       "t corner 1/1/0 3 1.5", "t hole 1/0/0 1"},
      {"t interpolateboundary 1/0/0 1", "t creasemethod 0/0/1 chaikin", "t crease 2/1/0 1 0 2.5",
       "t corner 1/1/0 3 1.5", "t hole 1/0/0 1"}};
  CHECK((tag_lines == expected_either[0] || tag_lines == expected_either[1]));
  const ObjSubdivisionTags back = read_obj_subdivision_tags(path);
  CHECK(back.boundary == BoundaryMode::edge_and_corner);
  CHECK(back.crease_method == CreaseMethod::chaikin);
}

TEST_CASE("an OBJ written by hand reads its positions, relative and slashed indices and tags", "[io]") {
  const fs::path path = tfo_write("hand.obj",
                                  "# by hand\nv 1.5 -2 0.25\nv 3 0 1e-3\nv -0.5 4 2\nvt 0 0\nvn 0 0 1\n"
                                  "v 7 8 9 1\nf 1/1/1 2/1/1 3/1/1\nf -1 -3//1 -2/1\n"
                                  "t crease 2/1/0 0 1 3.5\nt corner 1/1/0 2 2\nt hole 1/0/0 1\n"
                                  "t interpolateboundary 1/0/0 2\nt creasemethod 0/0/1 normal\n");
  const PolygonSoup soup = read_obj(path);
  CHECK(std::vector<Vec3>(soup.positions.begin(), soup.positions.end()) ==
        std::vector<Vec3>{Vec3(1.5, -2, 0.25), Vec3(3, 0, 1e-3), Vec3(-0.5, 4, 2), Vec3(7, 8, 9)});
  CHECK(std::vector<Index>(soup.face_offsets.begin(), soup.face_offsets.end()) ==
        std::vector<Index>{0, 3, 6});
  CHECK(std::vector<Index>(soup.face_vertices.begin(), soup.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 3, 1, 2});
  REQUIRE(soup.sharp_edges.size() == 1);
  CHECK(soup.sharp_edges[0] == std::pair<Index, Index>{0, 1});
  CHECK(soup.sharp_edge_weights == std::vector<float>{3.5f});
  REQUIRE(soup.sharp_vertices.size() == 1);
  CHECK(soup.sharp_vertices[0].first == 2);
  CHECK(soup.sharp_vertices[0].second == 2.0f);
  CHECK(soup.hole_faces == std::vector<Index>{1});
  const ObjSubdivisionTags tags = read_obj_subdivision_tags(path);
  CHECK(tags.boundary == BoundaryMode::edge_only);
  CHECK(tags.crease_method == CreaseMethod::uniform);
  const fs::path none =
      tfo_write("none.obj", "t interpolateboundary 1/0/0 0\nt smoothtriangles 0/0/1 smooth\n");
  CHECK(read_obj_subdivision_tags(none).boundary == BoundaryMode::none);
  CHECK(read_obj_subdivision_tags(none).smooth_triangles == true);
}

namespace {

struct TfoFacet {
  Vec3 normal;
  std::vector<Vec3> corners;
};

// The triangles each polygon of the soup is written as (a fan from its first corner), with the normal of
// the polygon by the right-hand rule.
std::vector<TfoFacet> tfo_expected_facets(const PolygonSoup& soup) {
  std::vector<TfoFacet> out;
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index first = soup.face_offsets[f], n = soup.face_offsets[f + 1] - first;
    const auto p = [&](Index i) { return soup.positions[soup.face_vertices[first + i]]; };
    const Vec3 normal = glm::normalize(glm::cross(p(1) - p(0), p(2) - p(0)));
    for (Index i = 1; i + 1 < n; ++i) out.push_back({normal, {p(0), p(i), p(i + 1)}});
  }
  return out;
}

}  // namespace

TEST_CASE("STL facets: a fan of each polygon in its winding, normals by the right-hand rule", "[io]") {
  const PolygonSoup soup = tfo_polygons();
  const Mesh mesh = build_mesh(soup);
  const std::vector<TfoFacet> expected = tfo_expected_facets(soup);
  REQUIRE(expected.size() == 5);

  const fs::path ascii = test::scratch_path("nome_text_formats", "two_a.stl");
  write_stl(ascii, mesh, StlFormat::ascii);
  std::vector<TfoFacet> facets;
  std::istringstream in(test::file_bytes(ascii));
  std::vector<std::string> first_last;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> w = tfo_words(line);
    if (w.empty()) continue;
    first_last.push_back(w[0]);
    auto numbers = [&](std::size_t from) {
      return Vec3(std::strtod(w[from].c_str(), nullptr), std::strtod(w[from + 1].c_str(), nullptr),
                  std::strtod(w[from + 2].c_str(), nullptr));
    };
    if (w[0] == "facet") {
      REQUIRE(w.size() == 5);
      CHECK(w[1] == "normal");
      facets.push_back({numbers(2), {}});
    } else if (w[0] == "vertex") {
      REQUIRE(!facets.empty());
      facets.back().corners.push_back(numbers(1));
    }
  }
  CHECK(first_last.front() == "solid");
  CHECK(first_last.back() == "endsolid");
  REQUIRE(facets.size() == expected.size());
  for (std::size_t t = 0; t < facets.size(); ++t) {
    INFO("facet " << t);
    REQUIRE(facets[t].corners.size() == 3);
    for (int k = 0; k < 3; ++k) {
      CHECK(facets[t].normal[k] == Approx(expected[t].normal[k]).margin(1e-8));
      for (std::size_t c = 0; c < 3; ++c)
        CHECK(facets[t].corners[c][k] == Approx(expected[t].corners[c][k]).epsilon(1e-8).margin(1e-15));
    }
  }

  const fs::path binary = test::scratch_path("nome_text_formats", "two_b.stl");
  write_stl(binary, mesh, StlFormat::binary);
  const std::string bytes = test::file_bytes(binary);
  REQUIRE(bytes.size() == 84 + 50 * expected.size());
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  CHECK(count == expected.size());
  for (std::size_t t = 0; t < expected.size(); ++t) {
    float record[12];
    std::memcpy(record, bytes.data() + 84 + 50 * t, 48);
    for (int k = 0; k < 3; ++k) {
      CHECK(record[k] == Approx(expected[t].normal[k]).margin(1e-6));
      for (std::size_t c = 0; c < 3; ++c)
        CHECK(record[3 + 3 * c + std::size_t(k)] == float(expected[t].corners[c][k]));
    }
    CHECK(bytes[84 + 50 * t + 48] == 0);
    CHECK(bytes[84 + 50 * t + 49] == 0);
  }
}

TEST_CASE("STL files written by hand read as welded triangles in their order", "[io]") {
  const fs::path ascii =
      tfo_write("hand_a.stl",
                "solid hand\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                "   vertex 2.5 0 0\n   vertex 2.5 1.25 0\n  endloop\n endfacet\n"
                " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 2.5 1.25 0\n"
                "   vertex -1 1.25 0.5\n  endloop\n endfacet\nendsolid hand\n");
  const PolygonSoup a = read_stl(ascii);
  CHECK(std::vector<Vec3>(a.positions.begin(), a.positions.end()) ==
        std::vector<Vec3>{Vec3(0, 0, 0), Vec3(2.5, 0, 0), Vec3(2.5, 1.25, 0), Vec3(-1, 1.25, 0.5)});
  CHECK(std::vector<Index>(a.face_vertices.begin(), a.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 0, 2, 3});
  // A binary file whose header starts with "solid" all the same: the size formula decides.
  std::string binary = "solid but binary";
  binary.resize(80, ' ');
  const std::uint32_t two = 2;
  binary.append(reinterpret_cast<const char*>(&two), 4);
  const float triangles[2][12] = {{0, 0, 1, 1, 2, 3, 4.5f, 2, 3, 1, 6, 3},
                                  {0, 0, 1, 1, 2, 3, 1, 6, 3, -2, 0.25f, 3}};
  for (const auto& t : triangles) {
    binary.append(reinterpret_cast<const char*>(t), 48);
    binary += std::string(2, '\0');
  }
  const PolygonSoup b = read_stl(tfo_write("hand_b.stl", binary));
  CHECK(std::vector<Vec3>(b.positions.begin(), b.positions.end()) ==
        std::vector<Vec3>{Vec3(1, 2, 3), Vec3(4.5, 2, 3), Vec3(1, 6, 3), Vec3(-2, 0.25, 3)});
  CHECK(std::vector<Index>(b.face_vertices.begin(), b.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 0, 2, 3});
}

TEST_CASE("a SIF written by hand reads each shell's vertices and triangles, numbered after the last",
          "[io]") {
  const std::string text =
      "(SIF_SFF 2 0 (* two shells *) (units mm) (bounds (0 0 0) (1 1 1))\n"
      " (solid (shell (vertices 3 (v 0 0 0) (v 1.5 0 -0.25) (v 0 2 0)) (triangles 1 (t 0 1 2)))\n"
      "        (shell (vertices 4 (v 5 0 0) (v 6 0 0) (v 6 1 0) (v 5 1 0)) (triangles 2 (t 0 1 2) (t 0 2 "
      "3)))))";
  const PolygonSoup soup = parse_sif(text, "hand.sif");
  CHECK(std::vector<Vec3>(soup.positions.begin(), soup.positions.end()) ==
        std::vector<Vec3>{Vec3(0, 0, 0), Vec3(1.5, 0, -0.25), Vec3(0, 2, 0), Vec3(5, 0, 0), Vec3(6, 0, 0),
                          Vec3(6, 1, 0), Vec3(5, 1, 0)});
  CHECK(std::vector<Index>(soup.face_vertices.begin(), soup.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 3, 4, 5, 3, 5, 6});
  // Paired: the second shell's two triangles are one square, kept in their winding.
  const PolygonSoup paired = parse_sif(text, "hand.sif", {true, 20});
  REQUIRE(paired.num_faces() == 2);
  std::vector<Index> quad(paired.face_vertices.begin() + 3, paired.face_vertices.end());
  REQUIRE(quad.size() == 4);
  while (quad[0] != 3) std::rotate(quad.begin(), quad.begin() + 1, quad.end());
  CHECK(quad == std::vector<Index>{3, 4, 5, 6});
}

TEST_CASE("an .slf scene places its points where its instances say", "[io]") {
  const fs::path path = tfo_write("hand.slf",
                                  "point a (1.5 -2 0.25) endpoint point b (3 0 0) endpoint\n"
                                  "point c (0 4 1) endpoint\n"
                                  "face x (a b c) endface\nobject o (x) endobject\n"
                                  "group g instance o id one endinstance\n"
                                  "  instance o id two translate (10 -1 0.5) endinstance endgroup\n");
  const scene::Scene s = read_scene(path);
  CHECK(test::vertex_position(s, "g_one_a") == Vec3(1.5, -2, 0.25));
  CHECK(test::vertex_position(s, "g_one_c") == Vec3(0, 4, 1));
  CHECK(test::vertex_position(s, "g_two_a") == Vec3(11.5, -3, 0.75));
  CHECK(test::vertex_position(s, "g_two_b") == Vec3(13, -1, 0.5));
}

TEST_CASE("a saved .nome writes each transform with its own numbers and reads back to the same places",
          "[io]") {
  const scene::Scene s = scene::Scene::from_text(
      "point a (1 0 0) endpoint point b (2 0 0) endpoint point c (1 1 0) endpoint\n"
      "surface S color (1 0 0) endsurface\n"
      "mesh m face f (a b c) surface S endface endmesh\n"
      "instance i m scale (2 3 0.5) rotate (0 0 1) (90) translate (1 2 3) surface S endinstance\n"
      "instance j m mirror (1 0 0 -3) endinstance\n",
      "t.nome");
  const std::string text = scene::to_nome_text(s);
  CHECK_THAT(text, Catch::Contains("face f (a b c) surface S endface\n"));
  CHECK_THAT(
      text,
      Catch::Contains(
          "instance i m scale (2 3 0.5) rotate (0 0 1) (90) translate (1 2 3) surface S endinstance\n"));
  CHECK_THAT(text, Catch::Contains("instance j m mirror (1 0 0 -3) endinstance\n"));
  const scene::Scene back = scene::Scene::from_text(text, "saved.nome");
  // b = (2 0 0): scaled (4 0 0), turned a quarter about z (0 4 0), moved (1 6 3); mirrored in x = 3: (4 0 0).
  for (const scene::Scene* scene : {&s, &back}) {
    const Vec3 p = test::vertex_position(*scene, "i_b");
    CHECK(p.x == Approx(1).margin(1e-12));
    CHECK(p.y == Approx(6).margin(1e-12));
    CHECK(p.z == Approx(3).margin(1e-12));
    CHECK(test::vertex_position(*scene, "j_b").x == Approx(4).margin(1e-12));
    CHECK(test::vertex_position(*scene, "j_c") == Vec3(5, 1, 0));
  }
}
