// PLY and binary glTF files read by the test itself: the PLY header and records as written, the GLB's
// chunks with a small JSON reader, its accessors and buffer views. Colours are checked against bytes
// worked out by hand (rounded, not truncated), normals against each corner's side of a Möbius band found
// by walking the fan here.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "nome/io/gltf.hpp"
#include "nome/io/ply.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "support/face_colors.hpp"
#include "support/scratch_files.hpp"
#include "support/shapes.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

// ---- PLY

struct PlyRecord {
  std::array<float, 3> position;
  std::array<int, 3> rgb;
};

struct PlyFile {
  std::string header;
  std::vector<PlyRecord> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

template <typename T>
T plyb_take(const std::string& bytes, std::size_t& at) {
  T v;
  REQUIRE(at + sizeof(T) <= bytes.size());
  std::memcpy(&v, bytes.data() + at, sizeof(T));  // little-endian, as this machine
  at += sizeof(T);
  return v;
}

PlyFile plyb_parse(const fs::path& path, std::size_t vertices, std::size_t faces) {
  const std::string bytes = test::file_bytes(path);
  const std::string end = "end_header\n";
  const std::size_t body = bytes.find(end) + end.size();
  PlyFile file;
  file.header = bytes.substr(0, body);
  std::size_t at = body;
  for (std::size_t v = 0; v < vertices; ++v) {
    PlyRecord r{};
    for (float& x : r.position) x = plyb_take<float>(bytes, at);
    for (int& c : r.rgb) c = plyb_take<std::uint8_t>(bytes, at);
    file.vertices.push_back(r);
  }
  for (std::size_t f = 0; f < faces; ++f) {
    std::vector<std::uint32_t> face(plyb_take<std::uint8_t>(bytes, at));
    for (std::uint32_t& i : face) i = plyb_take<std::uint32_t>(bytes, at);
    file.faces.push_back(face);
  }
  CHECK(at == bytes.size());
  return file;
}

// ---- GLB: a small JSON reader (objects, arrays, numbers, strings, true/false/null)

struct GlbJson {
  std::map<std::string, GlbJson> object;
  std::vector<GlbJson> array;
  double number = 0;
  std::string text;

  const GlbJson& operator[](const std::string& key) const {
    const auto it = object.find(key);
    REQUIRE(it != object.end());
    return it->second;
  }
  double number_or(const std::string& key, double fallback) const {
    const auto it = object.find(key);
    return it == object.end() ? fallback : it->second.number;
  }
};

GlbJson glb_json_value(const std::string& s, std::size_t& at);

void glb_json_space(const std::string& s, std::size_t& at) {
  while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at]))) ++at;
}

std::string glb_json_string(const std::string& s, std::size_t& at) {
  std::string out;
  for (++at; s.at(at) != '"'; ++at) {
    if (s[at] == '\\') ++at;
    out += s[at];
  }
  ++at;
  return out;
}

GlbJson glb_json_value(const std::string& s, std::size_t& at) {
  glb_json_space(s, at);
  GlbJson v;
  if (s.at(at) == '{') {
    ++at;
    for (glb_json_space(s, at); s.at(at) != '}'; glb_json_space(s, at)) {
      if (s[at] == ',') ++at, glb_json_space(s, at);
      const std::string key = glb_json_string(s, at);
      glb_json_space(s, at);
      REQUIRE(s.at(at) == ':');
      ++at;
      v.object[key] = glb_json_value(s, at);
    }
    ++at;
  } else if (s[at] == '[') {
    ++at;
    for (glb_json_space(s, at); s.at(at) != ']'; glb_json_space(s, at)) {
      if (s[at] == ',') ++at;
      v.array.push_back(glb_json_value(s, at));
    }
    ++at;
  } else if (s[at] == '"') {
    v.text = glb_json_string(s, at);
  } else if (std::isalpha(static_cast<unsigned char>(s[at]))) {
    while (std::isalpha(static_cast<unsigned char>(s[at]))) v.text += s[at++];
  } else {
    char* end = nullptr;
    v.number = std::strtod(s.c_str() + at, &end);
    REQUIRE(end != s.c_str() + at);
    at = std::size_t(end - s.c_str());
  }
  return v;
}

struct GlbFile {
  GlbJson json;
  std::string bin;
};

GlbFile glb_parse(const fs::path& path) {
  const std::string bytes = test::file_bytes(path);
  std::size_t at = 0;
  auto u32 = [&] {
    std::uint32_t v;
    REQUIRE(at + 4 <= bytes.size());
    std::memcpy(&v, bytes.data() + at, 4);
    at += 4;
    return v;
  };
  CHECK(u32() == 0x46546C67);  // "glTF"
  CHECK(u32() == 2);
  CHECK(u32() == bytes.size());
  GlbFile file;
  const std::uint32_t json_length = u32();
  CHECK(u32() == 0x4E4F534A);  // "JSON"
  const std::string json = bytes.substr(at, json_length);
  std::size_t j = 0;
  file.json = glb_json_value(json, j);
  at += json_length;
  const std::uint32_t bin_length = u32();
  CHECK(u32() == 0x004E4942);  // "BIN"
  file.bin = bytes.substr(at, bin_length);
  return file;
}

// Element i of accessor `a` as `n` values of type T.
template <typename T>
std::vector<T> glb_element(const GlbFile& file, int a, std::size_t i, int n) {
  const GlbJson& accessor = file.json["accessors"].array.at(std::size_t(a));
  const GlbJson& view = file.json["bufferViews"].array.at(std::size_t(accessor["bufferView"].number));
  const std::size_t stride = std::size_t(view.number_or("byteStride", double(sizeof(T) * std::size_t(n))));
  const std::size_t at =
      std::size_t(view.number_or("byteOffset", 0) + accessor.number_or("byteOffset", 0)) + i * stride;
  REQUIRE(at + sizeof(T) * std::size_t(n) <=
          std::size_t(view.number_or("byteOffset", 0) + view["byteLength"].number));
  std::vector<T> out(static_cast<std::size_t>(n));
  std::memcpy(out.data(), file.bin.data() + at, sizeof(T) * std::size_t(n));
  return out;
}

// The unit normal of a quad (the cross product of its diagonals), or of a polygon by Newell's formula.
Vec3 glb_face_normal(const PolygonSoup& soup, Index f) {
  const Index first = soup.face_offsets[f], n = soup.face_offsets[f + 1] - first;
  Vec3 sum(0.0);
  for (Index i = 0; i < n; ++i) {
    const Vec3& a = soup.positions[soup.face_vertices[first + i]];
    const Vec3& b = soup.positions[soup.face_vertices[first + (i + 1) % n]];
    sum += glm::cross(a, b);
  }
  return glm::normalize(sum);
}

// For each face around vertex v: its side relative to the first face found there (+1 or -1), from the
// directions in which faces sharing an edge at v run along it (opposite: same side).
std::map<Index, int> glb_fan_sides(const PolygonSoup& soup, Index v) {
  // Each face at v with its two neighbours at v: (u, does the face run v -> u).
  std::map<Index, std::vector<std::pair<Index, bool>>> sides_of;
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index first = soup.face_offsets[f], n = soup.face_offsets[f + 1] - first;
    for (Index i = 0; i < n; ++i)
      if (soup.face_vertices[first + i] == v) {
        sides_of[f].push_back({soup.face_vertices[first + (i + 1) % n], true});
        sides_of[f].push_back({soup.face_vertices[first + (i + n - 1) % n], false});
      }
  }
  std::map<Index, int> side{{sides_of.begin()->first, 1}};
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& [f, edges] : sides_of)
      for (const auto& [g, other] : sides_of) {
        if (f == g || !side.count(f) || side.count(g)) continue;
        for (const auto& [u, out] : edges)
          for (const auto& [w, other_out] : other)
            if (u == w && !side.count(g)) {
              side[g] = out != other_out ? side[f] : -side[f];
              grew = true;
            }
      }
  }
  REQUIRE(side.size() == sides_of.size());
  return side;
}

}  // namespace

TEST_CASE("a PLY's colours are rounded to bytes, each vertex once per colour, faces in their order", "[io]") {
  PolygonSoup soup = test::grid(3, 2);
  // Each with its byte by hand: 0.5 * 255 = 127.5 -> 128, 0.999 -> 254.7 -> 255, 0.3 -> 76.5 -> 77,
  // 0.1 -> 25.5 -> 26, 0.7 -> 178.5 -> 179; out of range clamps.
  const std::vector<std::pair<Color, std::array<int, 3>>> colours = {
      {{0.5f, 0.2f, 0.999f}, {128, 51, 255}}, {{0.3f, 0.0f, 1.0f}, {77, 0, 255}},
      {{0.1f, 0.7f, 0.5f}, {26, 179, 128}},   {{1.5f, -0.2f, 0.3f}, {255, 0, 77}},
      {{0.5f, 0.2f, 0.999f}, {128, 51, 255}}, {{0.999f, 0.999f, 0.1f}, {255, 255, 26}}};
  REQUIRE(soup.num_faces() == colours.size());
  for (const auto& c : colours) add_colors(soup.face_attributes).values().push_back(c.first);
  for (Vec3& p : soup.positions) p = Vec3(p.x * 1.25 + 0.1, p.y * -0.75, 0.3 * p.x * p.y);
  const Mesh mesh = build_mesh(soup);
  std::set<std::pair<Index, std::array<int, 3>>> expected_records;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.face_vertices(f)) expected_records.insert({v, colours[f].second});
  const fs::path path = test::scratch_path("nome_ply_glb_bytes", "grid.ply");
  write_ply(path, mesh);
  const PlyFile file = plyb_parse(path, expected_records.size(), mesh.num_faces());
  CHECK(file.header == "ply\nformat binary_little_endian 1.0\ncomment written by nome\nelement vertex " +
                           std::to_string(expected_records.size()) +
                           "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                           "property uchar green\nproperty uchar blue\nelement face 6\n"
                           "property list uchar uint vertex_indices\nend_header\n");
  REQUIRE(file.faces.size() == mesh.num_faces());
  std::set<std::pair<std::array<float, 3>, std::array<int, 3>>> distinct;
  for (const PlyRecord& r : file.vertices) distinct.insert({r.position, r.rgb});
  CHECK(distinct.size() == file.vertices.size());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto vs = mesh.face_vertices(f);
    REQUIRE(file.faces[f].size() == vs.size());
    for (std::size_t i = 0; i < vs.size(); ++i) {
      REQUIRE(file.faces[f][i] < file.vertices.size());
      const PlyRecord& r = file.vertices[file.faces[f][i]];
      for (int k = 0; k < 3; ++k) CHECK(r.position[std::size_t(k)] == float(mesh.position(vs[i])[k]));
      CHECK(r.rgb == colours[f].second);
    }
  }
}

TEST_CASE("PLY files written by hand read with their positions, faces and colours", "[io]") {
  const fs::path ascii = test::scratch_path("nome_ply_glb_bytes", "hand.ply");
  std::ofstream(ascii) << "ply\nformat ascii 1.0\ncomment by hand\nelement vertex 5\nproperty float x\n"
                          "property float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
                          "property uchar blue\nelement face 2\nproperty list uchar int vertex_indices\n"
                          "end_header\n0.5 -1 2 255 0 51\n3 1 -2.5 255 0 51\n1 4 0 255 0 51\n"
                          "-1 2 0.25 0 102 255\n1 4 0 0 102 255\n3 0 1 2\n4 3 1 4 0\n";
  const PolygonSoup a = read_ply(ascii);
  // The fifth vertex is at the third's position: one vertex.
  CHECK(a.positions.size() == 4);
  CHECK(std::vector<Vec3>(a.positions.begin(), a.positions.end()) ==
        std::vector<Vec3>{Vec3(0.5, -1, 2), Vec3(3, 1, -2.5), Vec3(1, 4, 0), Vec3(-1, 2, 0.25)});
  CHECK(std::vector<Index>(a.face_offsets.begin(), a.face_offsets.end()) == std::vector<Index>{0, 3, 7});
  CHECK(std::vector<Index>(a.face_vertices.begin(), a.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 3, 1, 2, 0});
  REQUIRE(test::face_colors(a).size() == 2);
  CHECK(test::face_colors(a)[0] == Color(1.0f, 0.0f, 0.2f));  // the first corner's vertex: 255 0 51
  CHECK(test::face_colors(a)[1] == Color(0.0f, 0.4f, 1.0f));  // 0 102 255

  // Big-endian doubles and a short count with int indices.
  std::string big =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list ushort int vertex_indices\nend_header\n";
  auto put_big = [&](const void* p, std::size_t n) {
    for (std::size_t i = n; i-- > 0;) big += static_cast<const char*>(p)[i];
  };
  for (double x : {0.1, -2.0, 3.5, 7.25, 0.0, -0.3, 1e-3, 2.0, 9.0}) put_big(&x, 8);
  const std::uint16_t three = 3;
  put_big(&three, 2);
  for (std::int32_t i : {2, 0, 1}) put_big(&i, 4);
  const fs::path binary = test::scratch_path("nome_ply_glb_bytes", "big.ply");
  std::ofstream(binary, std::ios::binary) << big;
  const PolygonSoup b = read_ply(binary);
  CHECK(std::vector<Vec3>(b.positions.begin(), b.positions.end()) ==
        std::vector<Vec3>{Vec3(0.1, -2.0, 3.5), Vec3(7.25, 0.0, -0.3), Vec3(1e-3, 2.0, 9.0)});
  CHECK(std::vector<Index>(b.face_vertices.begin(), b.face_vertices.end()) == std::vector<Index>{2, 0, 1});
  CHECK(test::face_colors(b).empty());
}

TEST_CASE("a .glb of a Möbius band holds each vertex once per side it shows, with that side's normal",
          "[io]") {
  PolygonSoup soup = test::mobius_band(12, 2);
  const Mesh mesh = build_mesh(soup);
  soup = to_soup(mesh);
  const fs::path path = test::scratch_path("nome_ply_glb_bytes", "band.glb");
  write_glb(path, mesh);
  const GlbFile file = glb_parse(path);
  CHECK(file.json["asset"]["version"].text == "2.0");
  REQUIRE(file.json["meshes"].array.size() == 1);
  REQUIRE(file.json["meshes"].array[0]["primitives"].array.size() == 1);
  const GlbJson& primitive = file.json["meshes"].array[0]["primitives"].array[0];
  CHECK(primitive.number_or("mode", 4) == 4);
  const int positions = int(primitive["attributes"]["POSITION"].number);
  const int normals = int(primitive["attributes"]["NORMAL"].number);
  const int indices = int(primitive["indices"].number);
  const GlbJson& accessors = file.json["accessors"];
  CHECK(accessors.array.at(std::size_t(positions))["componentType"].number == 5126);
  CHECK(accessors.array.at(std::size_t(positions))["type"].text == "VEC3");
  CHECK(accessors.array.at(std::size_t(normals))["componentType"].number == 5126);
  CHECK(accessors.array.at(std::size_t(indices))["componentType"].number == 5125);
  const std::size_t written = std::size_t(accessors.array.at(std::size_t(positions))["count"].number);
  CHECK(accessors.array.at(std::size_t(normals))["count"].number == double(written));
  const std::size_t corners = std::size_t(accessors.array.at(std::size_t(indices))["count"].number);
  CHECK(corners == 3 * 2 * soup.num_faces());  // each quad as two triangles

  // The side of each face at each vertex, and the normal each corner is drawn with: the signed sum of its
  // fan's unit face normals, turned to the corner's own side.
  std::map<std::pair<Index, Index>, Vec3> corner_normal;  // (face, vertex) -> unit normal
  std::size_t sides = 0;
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    const std::map<Index, int> side = glb_fan_sides(soup, v);
    Vec3 sum(0.0);
    std::set<int> seen;
    for (const auto& [f, s] : side) sum += double(s) * glb_face_normal(soup, f), seen.insert(s);
    sides += seen.size();
    for (const auto& [f, s] : side) corner_normal[{f, v}] = double(s) * glm::normalize(sum);
  }
  CHECK(written == sides);
  CHECK(sides > soup.num_vertices());  // the band shows both sides somewhere

  std::map<std::array<float, 3>, Index> vertex_at;
  for (Index v = 0; v < soup.num_vertices(); ++v)
    vertex_at[{float(soup.positions[v].x), float(soup.positions[v].y), float(soup.positions[v].z)}] = v;
  REQUIRE(vertex_at.size() == soup.num_vertices());
  std::vector<int> triangles_of_face(soup.num_faces(), 0);
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < corners / 3; ++t) {
    std::array<std::uint32_t, 3> index{};
    std::array<Index, 3> vertex{};
    for (std::size_t k = 0; k < 3; ++k) {
      index[k] = glb_element<std::uint32_t>(file, indices, 3 * t + k, 1)[0];
      REQUIRE(index[k] < written);
      const std::vector<float> p = glb_element<float>(file, positions, index[k], 3);
      const auto found = vertex_at.find({p[0], p[1], p[2]});
      REQUIRE(found != vertex_at.end());
      vertex[k] = found->second;
    }
    // The face whose corners these are, in its cyclic order.
    Index face = no_index;
    for (Index f = 0; f < soup.num_faces(); ++f) {
      const Index first = soup.face_offsets[f], n = soup.face_offsets[f + 1] - first;
      std::array<Index, 3> at{n, n, n};  // where each corner is in the face
      for (Index i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 3; ++k)
          if (soup.face_vertices[first + i] == vertex[k]) at[k] = i;
      if (at[0] == n || at[1] == n || at[2] == n) continue;
      const Index second = (at[1] + n - at[0]) % n, third = (at[2] + n - at[0]) % n;
      if (0 < second && second < third) face = f;
    }
    REQUIRE(face != no_index);
    ++triangles_of_face[face];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::vector<float> n = glb_element<float>(file, normals, index[k], 3);
      const Vec3 expected = corner_normal.at({face, vertex[k]});
      for (int i = 0; i < 3; ++i) CHECK(n[std::size_t(i)] == Approx(expected[i]).margin(1e-6));
      used.insert(index[k]);
    }
  }
  for (Index f = 0; f < soup.num_faces(); ++f) CHECK(triangles_of_face[f] == 2);
  CHECK(used.size() == written);  // every written vertex is used
}

TEST_CASE("a .glb written by hand reads its triangles welded by position, coloured by material", "[io]") {
  // Primitive 0: a square as two triangles (ushort indices); primitive 1: one triangle (no indices) sharing
  // the square's edge 1-2 by position.
  const float square[] = {0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3, 0};
  const std::uint16_t square_indices[] = {0, 1, 2, 0, 2, 3};
  const float flap[] = {2, 0, 0, 4.5f, 1.5f, -1, 2, 3, 0};
  std::string bin(reinterpret_cast<const char*>(square), sizeof square);
  bin.append(reinterpret_cast<const char*>(square_indices), sizeof square_indices);
  bin.append(reinterpret_cast<const char*>(flap), sizeof flap);
  const std::string json =
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" + std::to_string(bin.size()) +
      R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},)"
      R"({"buffer":0,"byteOffset":48,"byteLength":12},{"buffer":0,"byteOffset":60,"byteLength":36}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},)"
      R"({"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"},)"
      R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"}],)"
      R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.25,0.5,0.75,1]}},)"
      R"({"pbrMetallicRoughness":{"baseColorFactor":[1,0,0.5,1]}}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0},)"
      R"({"attributes":{"POSITION":2},"material":1}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
  std::string padded_json = json;
  while (padded_json.size() % 4) padded_json += ' ';
  std::string glb;
  auto put = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  put(0x46546C67);
  put(2);
  put(std::uint32_t(12 + 8 + padded_json.size() + 8 + bin.size()));
  put(std::uint32_t(padded_json.size()));
  put(0x4E4F534A);
  glb += padded_json;
  put(std::uint32_t(bin.size()));
  put(0x004E4942);
  glb += bin;
  const fs::path path = test::scratch_path("nome_ply_glb_bytes", "hand.glb");
  std::ofstream(path, std::ios::binary) << glb;
  const PolygonSoup soup = read_gltf(path);
  CHECK(std::vector<Vec3>(soup.positions.begin(), soup.positions.end()) ==
        std::vector<Vec3>{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 3, 0), Vec3(0, 3, 0), Vec3(4.5, 1.5, -1)});
  CHECK(std::vector<Index>(soup.face_vertices.begin(), soup.face_vertices.end()) ==
        std::vector<Index>{0, 1, 2, 0, 2, 3, 1, 4, 2});
  CHECK(test::face_colors(soup) ==
        std::vector<Color>{Color(0.25f, 0.5f, 0.75f), Color(0.25f, 0.5f, 0.75f), Color(1.0f, 0.0f, 0.5f)});
}
