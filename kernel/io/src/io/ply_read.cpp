// Reading PLY (ascii and binary): the header's elements and properties, then vertices and faces.
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "nome/error.hpp"
#include "nome/io/ply.hpp"
#include "nome/mesh/color_attribute.hpp"

namespace nome {
namespace {

struct PlyProperty {
  std::string name;
  std::string type;        // of the value, or of the list's items
  std::string count_type;  // a list's count; empty for a scalar
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { ascii, little_endian, big_endian };

std::size_t ply_type_size(const std::string& type) {
  static const std::map<std::string, std::size_t> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// Reads the values of one file, ascii or binary, as doubles.
class PlyValues {
 public:
  PlyValues(std::istream& in, PlyFormat format, std::string file)
      : in_(in), format_(format), file_(std::move(file)) {}

  double next(const std::string& type) {
    if (format_ == PlyFormat::ascii) {
      double v = 0;
      if (!(in_ >> v)) throw IoError(file_ + ": the data ends early or holds something not a number");
      return v;
    }
    unsigned char bytes[8] = {};
    const std::size_t size = ply_type_size(type);
    if (!in_.read(reinterpret_cast<char*>(bytes), std::streamsize(size)))
      throw IoError(file_ + ": the data ends early");
    if ((format_ == PlyFormat::big_endian) != (std::endian::native == std::endian::big))
      std::reverse(bytes, bytes + size);
    return decode(type, bytes);
  }

 private:
  static double decode(const std::string& t, const unsigned char* b) {
    auto as = [&](auto v) {
      std::memcpy(&v, b, sizeof(v));
      return double(v);
    };
    if (t == "char" || t == "int8") return as(std::int8_t{});
    if (t == "uchar" || t == "uint8") return as(std::uint8_t{});
    if (t == "short" || t == "int16") return as(std::int16_t{});
    if (t == "ushort" || t == "uint16") return as(std::uint16_t{});
    if (t == "int" || t == "int32") return as(std::int32_t{});
    if (t == "uint" || t == "uint32") return as(std::uint32_t{});
    if (t == "float" || t == "float32") return as(float{});
    return as(double{});
  }

  std::istream& in_;
  PlyFormat format_;
  std::string file_;
};

// The header up to end_header: the format and the elements.
std::vector<PlyElement> read_ply_header(std::istream& in, PlyFormat& format, const std::string& file) {
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) throw IoError(file + ":1: expected 'ply'");
  std::vector<PlyElement> elements;
  for (int number = 2; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    const std::string at = file + ":" + std::to_string(number) + ": ";
    if (word == "end_header") return elements;
    if (word == "format") {
      words >> word;
      if (word == "ascii")
        format = PlyFormat::ascii;
      else if (word == "binary_little_endian")
        format = PlyFormat::little_endian;
      else if (word == "binary_big_endian")
        format = PlyFormat::big_endian;
      else
        throw IoError(at + "unknown format '" + word + "'");
    } else if (word == "element") {
      PlyElement e;
      if (!(words >> e.name >> e.count)) throw IoError(at + "expected element NAME COUNT");
      elements.push_back(e);
    } else if (word == "property") {
      PlyProperty p;
      words >> p.type;
      if (p.type == "list") words >> p.count_type >> p.type;
      words >> p.name;
      if (elements.empty() || p.name.empty() || ply_type_size(p.type) == 0 ||
          (!p.count_type.empty() && ply_type_size(p.count_type) == 0))
        throw IoError(at + "expected property TYPE NAME or property list TYPE TYPE NAME after an element");
      elements.back().properties.push_back(p);
    } else if (word != "comment" && word != "obj_info" && !word.empty()) {
      throw IoError(at + "unknown header line '" + word + "'");
    }
  }
  throw IoError(file + ": the header has no end_header");
}

// One row of an element: a vertex's position and colour (channels < 0 when it has none), a face's vertex
// indices as the file numbers them.
struct PlyRow {
  std::array<double, 3> position{0, 0, 0};
  std::array<double, 3> color{-1, -1, -1};
  std::vector<double> indices;
  std::vector<double> others;  // the element's other numbers, in the order of its other properties
};

bool is_position_or_color(const std::string& name) {
  return name == "x" || name == "y" || name == "z" || name == "red" || name == "green" || name == "blue";
}

PlyRow read_ply_row(const PlyElement& e, PlyValues& values, const std::string& file) {
  PlyRow row;
  for (const PlyProperty& property : e.properties) {
    if (!property.count_type.empty()) {
      const double n = values.next(property.count_type);
      if (!(n >= 0 && n < 1e6)) throw IoError(file + ": a list of " + std::to_string(n) + " items");
      const bool is_indices = property.name == "vertex_indices" || property.name == "vertex_index";
      for (std::size_t k = 0; k < std::size_t(n); ++k) {
        const double v = values.next(property.type);
        if (is_indices) row.indices.push_back(v);
      }
      continue;
    }
    const double v = values.next(property.type);
    const char* axes[] = {"x", "y", "z"};
    const char* channels[] = {"red", "green", "blue"};
    const bool is_real = ply_type_size(property.type) >= 4 && property.type.find("int") == std::string::npos;
    for (std::size_t k = 0; k < 3; ++k) {
      if (property.name == axes[k]) row.position[k] = v;
      if (property.name == channels[k]) row.color[k] = is_real ? v : v / 255.0;
    }
    if (!is_position_or_color(property.name)) row.others.push_back(v);
  }
  return row;
}

// A face's other numbers become face attributes of their properties' names: whole numbers for integer
// types, floats for the others.
void add_face_numbers(const PlyElement& e, const PlyRow& row, Index face, Attributes& faces) {
  std::size_t k = 0;
  for (const PlyProperty& property : e.properties) {
    if (!property.count_type.empty() || is_position_or_color(property.name)) continue;
    const double v = row.others[k++];
    if (property.type.find("int") != std::string::npos || property.type.find("char") != std::string::npos ||
        property.type.find("short") != std::string::npos)
      faces.add<std::int32_t>(property.name, 0).set(face, std::int32_t(v));
    else
      faces.add<float>(property.name, 0.0f).set(face, float(v));
  }
}

}  // namespace

PolygonSoup read_ply(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(file + ": cannot open the file");
  PlyFormat format = PlyFormat::ascii;
  const std::vector<PlyElement> elements = read_ply_header(in, format, file);
  PlyValues values(in, format, file);
  PolygonSoup soup;
  std::vector<Index> welded_id;  // file vertex -> soup vertex
  std::vector<Color> colors;     // file vertex -> its colour, when the file has colours
  std::map<std::array<double, 3>, Index> welded;
  for (const PlyElement& e : elements)
    for (std::size_t i = 0; i < e.count; ++i) {
      const PlyRow row = read_ply_row(e, values, file);
      if (e.name == "vertex") {
        const auto [it, is_new] = welded.emplace(row.position, soup.num_vertices());
        if (is_new) soup.add_vertex(Vec3(row.position[0], row.position[1], row.position[2]));
        welded_id.push_back(it->second);
        if (row.color[0] >= 0)
          colors.push_back(Color(float(row.color[0]), float(row.color[1]), float(row.color[2])));
      } else if (e.name == "face") {
        std::vector<Index> face;
        for (double v : row.indices) {
          if (!(v >= 0 && v < double(welded_id.size())))
            throw IoError(file + ": face " + std::to_string(i) + " names vertex " +
                          std::to_string(std::int64_t(v)) + ", past the " + std::to_string(welded_id.size()) +
                          " vertices");
          face.push_back(welded_id[std::size_t(v)]);
        }
        soup.add_face(face);
        add_face_numbers(e, row, soup.num_faces() - 1, soup.face_attributes);
        if (colors.size() == welded_id.size() && !row.indices.empty())
          add_colors(soup.face_attributes).set(soup.num_faces() - 1, colors[std::size_t(row.indices[0])]);
      }
    }
  if (const Column<Color>* c = find_colors(soup.face_attributes);
      c && c->size() != std::size_t(soup.num_faces()))
    soup.face_attributes.remove(color_attribute);
  return soup;
}

}  // namespace nome
