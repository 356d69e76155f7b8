#include "nome/io/obj.hpp"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "io/obj_tag_lines.hpp"
#include "nome/atomic_file.hpp"
#include "nome/error.hpp"
#include "nome/io/obj_tags.hpp"

namespace nome {
namespace {

// tinyobjloader keeps a face's degree in an unsigned char.
constexpr size_t max_face_degree = 255;

// Where each `f` statement stands, so that faces tinyobjloader returns can be traced to a line.
struct FaceLine {
  int line = 0;
  std::vector<int> token_columns;  // 1-based column of each vertex token
};

// A pass over the file beside tinyobjloader's, for what it lets through: it reads "v 1 zero 0" as
// (1, 0, 0), and keeps a face's degree in a byte (a 300-gon becomes a 44-gon). So `v` and `f` statements
// are checked here token by token, with file:line:col. The pass also maps faces to lines for later
// messages, and reads `v` coordinates with strtod, which rounds correctly where tinyobjloader's own
// parser may be an ulp off (an OBJ written with %.17g must read back exactly).
struct LineScan {
  std::vector<FaceLine> faces;
  std::vector<Vec3> positions;
  std::vector<ObjTag> tags;  // OpenSubdiv's `t` lines
};

struct ObjToken {
  int column;  // 1-based
  std::string_view text;
};

// Whitespace-separated tokens after the statement keyword, up to a comment.
std::vector<ObjToken> tokens_after(const std::string& text, size_t i) {
  std::vector<ObjToken> out;
  for (;;) {
    i = text.find_first_not_of(" \t\r", i);
    if (i == std::string::npos || text[i] == '#') return out;
    const size_t end = std::min(text.find_first_of(" \t\r#", i), text.size());
    out.push_back({int(i) + 1, std::string_view(text).substr(i, end - i)});
    i = end;
  }
}

// A token as messages show it: quoted, and cut short when long.
std::string quoted(std::string_view token) {
  return "'" + std::string(token.substr(0, 40)) + (token.size() > 40 ? "...'" : "'");
}

// A face corner: v, v/vt, v//vn or v/vt/vn with non-zero whole numbers. Returns the vertex index.
std::optional<long long> corner_vertex_index(std::string_view token) {
  auto number = [&](size_t& i, long long& value) {
    const char* first = token.data() + i;
    const auto [ptr, ec] =
        std::from_chars(first + (*first == '+' ? 1 : 0), token.data() + token.size(), value);
    if (ec != std::errc() || ptr == first || value == 0 || value > INT32_MAX || value < -INT32_MAX)
      return false;
    i = size_t(ptr - token.data());
    return true;
  };
  size_t i = 0;
  long long vertex = 0, ignored = 0;
  if (!number(i, vertex)) return std::nullopt;
  for (int slashes = 0; i < token.size(); ++slashes) {
    if (slashes == 2 || token[i] != '/') return std::nullopt;
    ++i;
    if (i < token.size() && token[i] != '/' && !number(i, ignored)) return std::nullopt;
  }
  return vertex;
}

LineScan scan_lines(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  LineScan scan;
  const std::string file = path.string();
  auto fail = [&](int line, int column, const std::string& what) {
    throw IoError(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
  };
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const size_t i = text.find_first_not_of(" \t");
    // Only the one-letter statements `v` and `f` (not vt, vn, fo...).
    if (i == std::string::npos || (i + 1 < text.size() && text.find_first_of(" \t\r#", i + 1) != i + 1))
      continue;
    if (text[i] == 't') {
      scan.tags.push_back(parse_obj_tag(file, line, text));
    } else if (text[i] == 'v') {
      const std::vector<ObjToken> tokens = tokens_after(text, i + 1);
      // x y z, x y z w, or x y z r g b (a common extension for vertex colours).
      if (tokens.size() != 3 && tokens.size() != 4 && tokens.size() != 6)
        fail(line, int(i) + 1,
             "expected 3 coordinates after 'v', found " + std::to_string(tokens.size()) + " numbers");
      Vec3 v;
      for (size_t k = 0; k < tokens.size(); ++k) {
        const std::string token(tokens[k].text);
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end != token.c_str() + token.size())
          fail(line, tokens[k].column, "expected a number, found " + quoted(tokens[k].text));
        if (!std::isfinite(value))
          fail(line, tokens[k].column, "expected a finite number, found " + quoted(tokens[k].text));
        if (k < 3) v[int(k)] = value;
      }
      scan.positions.push_back(v);
    } else if (text[i] == 'f') {
      FaceLine face{line, {}};
      const std::vector<ObjToken> tokens = tokens_after(text, i + 1);
      for (const ObjToken& t : tokens) {
        const auto index = corner_vertex_index(t.text);
        if (!index)
          fail(line, t.column,
               "expected a vertex index (a non-zero whole number, as in 3, 3/1, 3//2 or 3/1/2), found " +
                   quoted(t.text));
        if (*index < 0 && -*index > (long long)scan.positions.size())
          fail(line, t.column,
               "vertex index out of range (" + std::to_string(scan.positions.size()) +
                   " vertices are defined before this line)");
        face.token_columns.push_back(t.column);
      }
      if (tokens.size() > max_face_degree)
        fail(line, 1,
             "a face has " + std::to_string(tokens.size()) + " vertices; at most " +
                 std::to_string(max_face_degree) + " are supported");
      scan.faces.push_back(std::move(face));
    }
  }
  return scan;
}

std::string first_line(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

}  // namespace

PolygonSoup read_obj(const std::filesystem::path& path) {
  const std::string file = path.string();
  {
    std::ifstream probe(path);
    if (!probe) throw IoError(file + ": cannot open");
  }
  const LineScan scan = scan_lines(path);
  const std::vector<FaceLine>& face_lines = scan.faces;
  for (const FaceLine& fl : face_lines)
    if (fl.token_columns.size() < 3)
      throw IoError(file + ":" + std::to_string(fl.line) +
                    ":1: expected a face with at least 3 vertices, found " +
                    std::to_string(fl.token_columns.size()));

  // No material reader: materials are not used, and `mtllib` may name any path (`../../dev/zero` read
  // until memory ran out, a FIFO blocked forever).
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings, errors;
  std::ifstream in(path);
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &in, nullptr, false, false)) {
    const std::string err = first_line(errors);
    throw IoError(file + ": " + (err.empty() ? "cannot parse" : err));
  }
  PolygonSoup soup;
  if (scan.positions.size() * 3 == attrib.vertices.size()) {
    soup.positions.assign(scan.positions.begin(), scan.positions.end());
  } else {
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
      soup.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
  }

  size_t face_number = 0;
  for (const auto& shape : shapes) {
    size_t offset = 0;
    for (unsigned char degree : shape.mesh.num_face_vertices) {
      const FaceLine* where = face_number < face_lines.size() ? &face_lines[face_number] : nullptr;
      for (size_t k = 0; k < degree; ++k) {
        const int index = shape.mesh.indices[offset + k].vertex_index;
        if (index < 0 || size_t(index) >= soup.positions.size()) {
          std::string at =
              where ? ":" + std::to_string(where->line) + ":" +
                          std::to_string(k < where->token_columns.size() ? where->token_columns[k] : 1)
                    : "";
          throw IoError(file + at + ": vertex index out of range (the file has " +
                        std::to_string(soup.positions.size()) + " vertices)");
        }
        soup.face_vertices.push_back(Index(index));
      }
      soup.face_offsets.push_back(Index(soup.face_vertices.size()));
      offset += degree;
      ++face_number;
    }
  }
  apply_obj_tags(file, scan.tags, soup);
  return soup;
}

}  // namespace nome
