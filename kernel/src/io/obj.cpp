#include "nome/io/obj.hpp"

#include <tiny_obj_loader.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "nome/error.hpp"
#include "nome/io/atomic_file.hpp"

namespace nome {
namespace {

// Where each `f` statement stands, so that faces tinyobjloader returns can be traced to a line.
struct FaceLine {
  int line = 0;
  std::vector<int> token_columns;  // 1-based column of each vertex token
};

// A light pass over the file beside tinyobjloader's: it maps faces to lines for messages, and reads
// `v` coordinates with strtod, which rounds correctly where tinyobjloader's own parser may be an ulp
// off (an OBJ written with %.17g must read back exactly).
struct LineScan {
  std::vector<FaceLine> faces;
  std::vector<Vec3> positions;
};

LineScan scan_lines(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  LineScan scan;
  std::vector<FaceLine>& faces = scan.faces;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    size_t i = text.find_first_not_of(" \t");
    if (i != std::string::npos && text.compare(i, 2, "v ") == 0) {
      const char* p = text.c_str() + i + 2;
      char* end = nullptr;
      Vec3 v;
      for (int k = 0; k < 3; ++k, p = end) v[k] = std::strtod(p, &end);
      scan.positions.push_back(v);
      continue;
    }
    if (i == std::string::npos || text[i] != 'f' || i + 1 >= text.size() ||
        (text[i + 1] != ' ' && text[i + 1] != '\t'))
      continue;
    FaceLine face{line, {}};
    for (i = i + 1; i < text.size();) {
      i = text.find_first_not_of(" \t\r", i);
      if (i == std::string::npos || text[i] == '#') break;
      face.token_columns.push_back(int(i) + 1);
      i = text.find_first_of(" \t\r", i);
    }
    faces.push_back(std::move(face));
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

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(file, config)) {
    const std::string err = first_line(reader.Error());
    throw IoError(file + ": " + (err.empty() ? "cannot parse" : err));
  }
  const auto& attrib = reader.GetAttrib();
  PolygonSoup soup;
  if (scan.positions.size() * 3 == attrib.vertices.size()) {
    soup.positions = scan.positions;
  } else {
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
      soup.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
  }

  size_t face_number = 0;
  for (const auto& shape : reader.GetShapes()) {
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
  return soup;
}

void write_obj(const std::filesystem::path& path, const Mesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# written by nome: " << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces\n";
    char buf[96];
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
      const Vec3& p = mesh.position(v);
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
      out << buf;
    }
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      out << 'f';
      for (Index v : mesh.face_vertices(f)) out << ' ' << (v + 1);
      out << '\n';
    }
  });
}

}  // namespace nome
