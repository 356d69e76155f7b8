// 3MF packages read by the test itself: the zip's central directory, each entry stored or deflated (zlib's
// raw inflate), the model XML's unit and numbers parsed as text. The writer's unit attribute and
// coordinates, and the reader's reading of a package written here, are checked against numbers chosen to
// be exact in a float and in short decimals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#ifdef NOME_HAVE_ZLIB
#include <zlib.h>
#endif

#include "nome/error.hpp"
#include "nome/io/three_mf.hpp"
#include "nome/ops/pipeline.hpp"
#include "support/face_colors.hpp"
#include "support/scratch_files.hpp"

using namespace nome;
namespace fs = std::filesystem;

namespace {

std::uint32_t tmf_u16(const std::string& b, std::size_t at) {
  return std::uint32_t(std::uint8_t(b.at(at))) | std::uint32_t(std::uint8_t(b.at(at + 1))) << 8;
}

std::uint32_t tmf_u32(const std::string& b, std::size_t at) {
  return tmf_u16(b, at) | tmf_u16(b, at + 2) << 16;
}

std::uint64_t tmf_u64(const std::string& b, std::size_t at) {
  return std::uint64_t(tmf_u32(b, at)) | std::uint64_t(tmf_u32(b, at + 4)) << 32;
}

// The entries of a zip by name, uncompressed: the central directory gives each entry's sizes and the
// offset of its local header (zip64 extra fields where a size is 0xffffffff).
std::map<std::string, std::string> tmf_unzip(const std::string& zip) {
  std::size_t end = zip.size() - 22;
  while (tmf_u32(zip, end) != 0x06054b50) --end;
  std::uint64_t entries = tmf_u16(zip, end + 10);
  std::uint64_t at = tmf_u32(zip, end + 16);
  if (at == 0xffffffff && end >= 20 && tmf_u32(zip, end - 20) == 0x07064b50) {
    // Zip64: the locator before the end record names the zip64 end record.
    const std::uint64_t record = tmf_u64(zip, end - 20 + 8);
    REQUIRE(tmf_u32(zip, record) == 0x06064b50);
    entries = tmf_u64(zip, record + 32);
    at = tmf_u64(zip, record + 48);
  }
  std::map<std::string, std::string> files;
  for (std::uint64_t i = 0; i < entries; ++i) {
    REQUIRE(tmf_u32(zip, at) == 0x02014b50);
    const std::uint32_t method = tmf_u16(zip, at + 10);
    std::uint64_t packed = tmf_u32(zip, at + 20), size = tmf_u32(zip, at + 24);
    const std::uint32_t name_length = tmf_u16(zip, at + 28), extra_length = tmf_u16(zip, at + 30),
                        comment_length = tmf_u16(zip, at + 32);
    std::uint64_t local = tmf_u32(zip, at + 42);
    const std::string name = zip.substr(at + 46, name_length);
    for (std::size_t x = at + 46 + name_length; x < at + 46 + name_length + extra_length;) {
      const std::uint32_t id = tmf_u16(zip, x), length = tmf_u16(zip, x + 2);
      if (id == 1) {
        std::size_t field = x + 4;
        if (size == 0xffffffff) size = tmf_u64(zip, field), field += 8;
        if (packed == 0xffffffff) packed = tmf_u64(zip, field), field += 8;
        if (local == 0xffffffff) local = tmf_u64(zip, field);
      }
      x += 4 + length;
    }
    REQUIRE(tmf_u32(zip, local) == 0x04034b50);
    const std::size_t data = local + 30 + tmf_u16(zip, local + 26) + tmf_u16(zip, local + 28);
    const std::string bytes = zip.substr(data, packed);
    if (method == 0) {
      files[name] = bytes;
    } else {
      REQUIRE(method == 8);
#ifdef NOME_HAVE_ZLIB
      std::string out(size, '\0');
      z_stream s{};
      REQUIRE(inflateInit2(&s, -15) == Z_OK);
      s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
      s.avail_in = uInt(bytes.size());
      s.next_out = reinterpret_cast<Bytef*>(out.data());
      s.avail_out = uInt(out.size());
      CHECK(inflate(&s, Z_FINISH) == Z_STREAM_END);
      CHECK(s.total_out == size);
      inflateEnd(&s);
      files[name] = out;
#else
      FAIL("a deflated zip entry and no zlib to inflate it");
#endif
    }
    at += 46 + name_length + extra_length + comment_length;
  }
  return files;
}

// The value of attribute `name` in the element starting at `at` (up to its '>').
std::string tmf_attribute(const std::string& xml, std::size_t at, const std::string& name) {
  const std::size_t close = xml.find('>', at);
  const std::size_t key = xml.find(" " + name + "=\"", at);
  if (key == std::string::npos || key > close) return "";
  const std::size_t first = key + name.size() + 3;
  return xml.substr(first, xml.find('"', first) - first);
}

struct TmfObject {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
};

struct TmfModel {
  std::string unit;
  std::vector<TmfObject> objects;
};

// The model part's unit and each object's <vertex> and <triangle> elements, in file order.
TmfModel tmf_model(const fs::path& path) {
  const std::map<std::string, std::string> files = tmf_unzip(test::file_bytes(path));
  REQUIRE(files.count("3D/3dmodel.model") == 1);
  const std::string& xml = files.at("3D/3dmodel.model");
  TmfModel model;
  model.unit = tmf_attribute(xml, xml.find("<model"), "unit");
  for (std::size_t at = xml.find("<object"); at != std::string::npos; at = xml.find("<object", at + 1)) {
    TmfObject object;
    const std::size_t end = xml.find("</object>", at);
    for (std::size_t v = xml.find("<vertex ", at); v < end; v = xml.find("<vertex ", v + 1))
      object.vertices.push_back({std::strtod(tmf_attribute(xml, v, "x").c_str(), nullptr),
                                 std::strtod(tmf_attribute(xml, v, "y").c_str(), nullptr),
                                 std::strtod(tmf_attribute(xml, v, "z").c_str(), nullptr)});
    for (std::size_t t = xml.find("<triangle ", at); t < end; t = xml.find("<triangle ", t + 1))
      object.triangles.push_back({std::atoi(tmf_attribute(xml, t, "v1").c_str()),
                                  std::atoi(tmf_attribute(xml, t, "v2").c_str()),
                                  std::atoi(tmf_attribute(xml, t, "v3").c_str())});
    model.objects.push_back(object);
  }
  return model;
}

// Two tetrahedra apart (two parts), every coordinate a short binary fraction.
PolygonSoup tmf_two_tetrahedra() {
  PolygonSoup soup;
  for (const Vec3& p :
       {Vec3(0.5, -1.25, 2), Vec3(3.75, 0.125, -0.5), Vec3(-2.5, 4, 1.5), Vec3(1, 1, -3.25),
        Vec3(10.5, 0.25, 0.75), Vec3(12, 0.25, 0.75), Vec3(10.5, 2.5, 0.75), Vec3(10.5, 0.25, -1.5)})
    soup.add_vertex(p);
  for (Index base : {Index(0), Index(4)})
    for (const auto& t : {std::array<Index, 3>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}})
      soup.add_face({base + t[0], base + t[1], base + t[2]});
  return soup;
}

// Each written triangle names the corners of one face of the soup in its cyclic order, positions scaled by
// `scale` exactly; every face once.
void tmf_check_triangles(const TmfModel& model, const PolygonSoup& soup, double scale) {
  std::map<std::array<double, 3>, Index> vertex_at;
  for (Index v = 0; v < soup.num_vertices(); ++v)
    vertex_at[{soup.positions[v].x * scale, soup.positions[v].y * scale, soup.positions[v].z * scale}] = v;
  std::map<std::array<Index, 3>, int> faces;  // each rotated to start at its smallest vertex
  auto rotated = [](std::array<Index, 3> t) {
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    return t;
  };
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index* c = soup.face_vertices.data() + soup.face_offsets[f];
    ++faces[rotated({c[0], c[1], c[2]})];
  }
  REQUIRE(model.objects.size() == 2);
  for (const TmfObject& object : model.objects) {
    CHECK(object.vertices.size() == 4);  // each part's own vertices, each once
    for (const auto& t : object.triangles) {
      std::array<Index, 3> corners{};
      for (int k = 0; k < 3; ++k) {
        REQUIRE(t[k] >= 0);
        REQUIRE(std::size_t(t[k]) < object.vertices.size());
        const auto found = vertex_at.find(object.vertices[std::size_t(t[k])]);
        REQUIRE(found != vertex_at.end());
        corners[k] = found->second;
      }
      CHECK(--faces[rotated(corners)] == 0);
    }
  }
  for (const auto& [face, left] : faces) CHECK(left == 0);
}

}  // namespace

TEST_CASE("a 3MF names its unit and holds the mesh's coordinates in it, as they are, for every unit",
          "[io]") {
  const PolygonSoup soup = tmf_two_tetrahedra();
  const Mesh mesh = build_mesh(soup);
  const std::pair<LengthUnit, const char*> units[] = {{LengthUnit::millimeter, "millimeter"},
                                                      {LengthUnit::centimeter, "centimeter"},
                                                      {LengthUnit::inch, "inch"},
                                                      {LengthUnit::meter, "meter"}};
  for (const auto& [unit, name] : units)
    for (double scale : {1.0, 2.5}) {
      INFO(name << " scale " << scale);
      const fs::path path = test::scratch_path("nome_3mf_package", std::string(name) + ".3mf");
      write_3mf(path, mesh, {unit, scale});
      const TmfModel model = tmf_model(path);
      CHECK(model.unit == name);
      tmf_check_triangles(model, soup, scale);
      // The kernel's reader: the same unit, the same numbers (no conversion either way).
      const ThreeMfModel back = read_3mf(path);
      CHECK(back.unit == unit);
      REQUIRE(back.objects.size() == model.objects.size());
      for (std::size_t o = 0; o < back.objects.size(); ++o) {
        REQUIRE(back.objects[o].vertices.size() == model.objects[o].vertices.size());
        for (std::size_t v = 0; v < back.objects[o].vertices.size(); ++v)
          for (int k = 0; k < 3; ++k)
            CHECK(back.objects[o].vertices[v][k] == model.objects[o].vertices[v][k]);
        REQUIRE(back.objects[o].triangles.size() == model.objects[o].triangles.size());
        for (std::size_t t = 0; t < back.objects[o].triangles.size(); ++t)
          for (int k = 0; k < 3; ++k)
            CHECK(back.objects[o].triangles[t][k] == Index(model.objects[o].triangles[t][k]));
      }
    }
  CHECK(parse_length_unit("mm") == LengthUnit::millimeter);
  CHECK(parse_length_unit("cm") == LengthUnit::centimeter);
  CHECK(parse_length_unit("in") == LengthUnit::inch);
  CHECK(parse_length_unit("m") == LengthUnit::meter);
  CHECK_FALSE(parse_length_unit("ft"));
  CHECK(std::string(to_string(LengthUnit::centimeter)) == "cm");
  CHECK(std::string(to_string(LengthUnit::inch)) == "in");
  CHECK(std::string(to_string(LengthUnit::meter)) == "m");
}

#ifdef NOME_HAVE_ZLIB
namespace {

void tmf_put(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out += char((value >> (8 * i)) & 0xff);
}

// A zip of stored entries (what any 3MF reader must take), with their CRCs.
std::string tmf_stored_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string zip, directory;
  for (const auto& [name, data] : entries) {
    const std::uint32_t crc =
        std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(data.data()), uInt(data.size())));
    const std::size_t local = zip.size();
    tmf_put(zip, 0x04034b50, 4);
    tmf_put(zip, 20, 2);
    tmf_put(zip, 0, 2);
    tmf_put(zip, 0, 2);  // stored
    tmf_put(zip, 0, 4);  // time, date
    tmf_put(zip, crc, 4);
    tmf_put(zip, data.size(), 4);
    tmf_put(zip, data.size(), 4);
    tmf_put(zip, name.size(), 2);
    tmf_put(zip, 0, 2);
    zip += name + data;
    tmf_put(directory, 0x02014b50, 4);
    tmf_put(directory, 20, 2);
    tmf_put(directory, 20, 2);
    tmf_put(directory, 0, 2);
    tmf_put(directory, 0, 2);
    tmf_put(directory, 0, 4);
    tmf_put(directory, crc, 4);
    tmf_put(directory, data.size(), 4);
    tmf_put(directory, data.size(), 4);
    tmf_put(directory, name.size(), 2);
    tmf_put(directory, 0, 6);  // extra, comment, disk
    tmf_put(directory, 0, 2);
    tmf_put(directory, 0, 4);
    tmf_put(directory, local, 4);
    directory += name;
  }
  const std::size_t start = zip.size();
  zip += directory;
  tmf_put(zip, 0x06054b50, 4);
  tmf_put(zip, 0, 4);
  tmf_put(zip, entries.size(), 2);
  tmf_put(zip, entries.size(), 2);
  tmf_put(zip, directory.size(), 4);
  tmf_put(zip, start, 4);
  tmf_put(zip, 0, 2);
  return zip;
}

}  // namespace

TEST_CASE("a 3MF written by hand reads with its unit and its coordinates as written", "[io]") {
  const std::string types =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default Extension=\"rels\" "
      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default "
      "Extension=\"model\" "
      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>";
  const std::string rels =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
      "Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
      "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
  const std::pair<const char*, LengthUnit> units[] = {{"millimeter", LengthUnit::millimeter},
                                                      {"centimeter", LengthUnit::centimeter},
                                                      {"inch", LengthUnit::inch},
                                                      {"meter", LengthUnit::meter}};
  for (const auto& [name, unit] : units) {
    INFO(name);
    const std::string model =
        std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"") + name +
        "\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">"
        "<resources><object id=\"1\" type=\"model\"><mesh><vertices>"
        "<vertex x=\"1.5\" y=\"-2.25\" z=\"0.125\"/><vertex x=\"4\" y=\"0\" z=\"0.5\"/>"
        "<vertex x=\"-3.75\" y=\"6.5\" z=\"1\"/><vertex x=\"0.25\" y=\"0.75\" "
        "z=\"-8\"/></vertices><triangles>"
        "<triangle v1=\"0\" v2=\"2\" v3=\"1\"/><triangle v1=\"0\" v2=\"1\" v3=\"3\"/>"
        "<triangle v1=\"1\" v2=\"2\" v3=\"3\"/><triangle v1=\"0\" v2=\"3\" v3=\"2\"/></triangles></mesh>"
        "</object></resources><build><item objectid=\"1\"/></build></model>";
    const fs::path path = test::scratch_path("nome_3mf_package", std::string("hand_") + name + ".3mf");
    std::ofstream(path, std::ios::binary) << tmf_stored_zip(
        {{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
    const ThreeMfModel read = read_3mf(path);
    CHECK(read.unit == unit);
    REQUIRE(read.objects.size() == 1);
    const std::vector<Vec3> expected = {Vec3(1.5, -2.25, 0.125), Vec3(4, 0, 0.5), Vec3(-3.75, 6.5, 1),
                                        Vec3(0.25, 0.75, -8)};
    CHECK(read.objects[0].vertices == expected);
    const std::vector<std::array<Index, 3>> triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    CHECK(read.objects[0].triangles == triangles);
    const PolygonSoup soup = three_mf_polygons(read);
    CHECK(std::vector<Index>(soup.face_vertices.begin(), soup.face_vertices.end()) ==
          std::vector<Index>{0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2});
  }
}
#endif

namespace {

// A strip of five unit quads along x (face i spans x i..i+1), coloured red, none, blue, none, green: the
// faces without a colour come after a coloured one, and the first face has one.
PolygonSoup tmf_partly_coloured_strip() {
  PolygonSoup soup;
  for (int i = 0; i <= 5; ++i) {
    soup.add_vertex(Vec3(i, 0, 0));
    soup.add_vertex(Vec3(i, 1, 0));
  }
  for (Index i = 0; i < 5; ++i) soup.add_face({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  test::set_face_colors(soup.face_attributes,
                        {Color(1, 0, 0), no_face_color, Color(0, 0, 1), no_face_color, Color(0, 1, 0)});
  return soup;
}

// Each written triangle's colour as the model XML gives it (#RRGGBBAA): the colour group its `pid` names
// at its `p1`, or the object's own `pid` and `pindex` for a triangle without one; with the x of its
// corners' centre.
std::vector<std::pair<double, std::string>> tmf_triangle_colors(const fs::path& path) {
  const std::map<std::string, std::string> files = tmf_unzip(test::file_bytes(path));
  REQUIRE(files.count("3D/3dmodel.model") == 1);
  const std::string& xml = files.at("3D/3dmodel.model");
  std::map<std::string, std::vector<std::string>> groups;
  for (std::size_t at = xml.find("<m:colorgroup"); at != std::string::npos;
       at = xml.find("<m:colorgroup", at + 1)) {
    std::vector<std::string>& colors = groups[tmf_attribute(xml, at, "id")];
    const std::size_t end = xml.find("</m:colorgroup>", at);
    for (std::size_t c = xml.find("<m:color ", at); c < end; c = xml.find("<m:color ", c + 1))
      colors.push_back(tmf_attribute(xml, c, "color"));
  }
  std::vector<std::pair<double, std::string>> triangles;
  for (std::size_t at = xml.find("<object"); at != std::string::npos; at = xml.find("<object", at + 1)) {
    const std::string object_group = tmf_attribute(xml, at, "pid"),
                      object_index = tmf_attribute(xml, at, "pindex");
    const std::size_t end = xml.find("</object>", at);
    std::vector<double> xs;
    for (std::size_t v = xml.find("<vertex ", at); v < end; v = xml.find("<vertex ", v + 1))
      xs.push_back(std::strtod(tmf_attribute(xml, v, "x").c_str(), nullptr));
    for (std::size_t t = xml.find("<triangle ", at); t < end; t = xml.find("<triangle ", t + 1)) {
      double x = 0;
      for (const char* corner : {"v1", "v2", "v3"})
        x += xs.at(std::size_t(std::atoi(tmf_attribute(xml, t, corner).c_str())));
      std::string group = tmf_attribute(xml, t, "pid"), index = tmf_attribute(xml, t, "p1");
      if (index.empty()) {
        group = object_group;
        index = object_index;
      }
      REQUIRE_FALSE(index.empty());
      triangles.push_back({x / 3, groups.at(group).at(std::size_t(std::atoi(index.c_str())))});
    }
  }
  return triangles;
}

// The colour the face under x has: the faces without one are written light grey (0.75, 191 a channel).
std::string tmf_strip_color(double x) {
  const char* const colors[] = {"#FF0000FF", "#BFBFBFFF", "#0000FFFF", "#BFBFBFFF", "#00FF00FF"};
  return colors[std::size_t(std::clamp(int(std::floor(x)), 0, 4))];
}

}  // namespace

TEST_CASE("a 3MF writes the faces of a partly coloured mesh without a colour light grey, not a neighbour's",
          "[io]") {
  const PolygonSoup soup = tmf_partly_coloured_strip();
  const fs::path path = test::scratch_path("nome_3mf_package", "strip.3mf");
  write_3mf(path, build_mesh(soup), {});
  const auto triangles = tmf_triangle_colors(path);
  REQUIRE(triangles.size() == 10);
  for (const auto& [x, color] : triangles) {
    INFO("triangle at x " << x);
    CHECK(color == tmf_strip_color(x));
  }
  // Read back with lib3mf: every triangle with its colour.
  const ThreeMfModel back = read_3mf(path);
  REQUIRE(back.objects.size() == 1);
  const ThreeMfModel::Object& strip = back.objects[0];
  REQUIRE(strip.colors.size() == strip.triangles.size());
  const Color expected[] = {Color(1, 0, 0), Color(0.75f), Color(0, 0, 1), Color(0.75f), Color(0, 1, 0)};
  for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
    double x = 0;
    for (Index v : strip.triangles[t]) x += strip.vertices[v].x / 3;
    INFO("triangle at x " << x);
    CHECK(glm::length(strip.colors[t] - expected[std::size_t(std::clamp(int(std::floor(x)), 0, 4))]) < 0.01);
  }

  // Subdivided and thickened: every face of the solid takes its source face's colour, or grey.
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{soup, {}, {}});
  PipelineSettings settings;
  settings.subdivision_levels = 1;
  settings.offset_distance = 0.1;
  write_3mf(path, pipeline.run(settings), {});
  const auto solid = tmf_triangle_colors(path);
  CHECK(solid.size() > 40);
  std::map<std::string, int> counted;
  for (const auto& [x, color] : solid) {
    // A centre on a boundary between faces (a rim's end) cannot tell which face it came from.
    if (std::abs(x - std::round(x)) < 0.05) continue;
    INFO("triangle at x " << x);
    CHECK(color == tmf_strip_color(x));
    ++counted[color];
  }
  CHECK(counted.size() == 4);
}
