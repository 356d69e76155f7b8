#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unordered_map>

#include "io/stl_detect.hpp"
#include "nome/error.hpp"
#include "nome/io/stl.hpp"

namespace nome {
namespace {

struct FloatTripleHash {
  size_t operator()(const std::array<float, 3>& p) const {
    std::uint32_t bits[3];
    std::memcpy(bits, p.data(), sizeof bits);
    return (size_t(bits[0]) * 73856093u) ^ (size_t(bits[1]) * 19349663u) ^ (size_t(bits[2]) * 83492791u);
  }
};

class Welder {
 public:
  explicit Welder(PolygonSoup& soup) : soup_(soup) {}
  Index vertex(const std::array<float, 3>& p) {
    auto [it, inserted] = ids_.try_emplace(p, soup_.num_vertices());
    if (inserted) soup_.add_vertex(Vec3(p[0], p[1], p[2]));
    return it->second;
  }

 private:
  PolygonSoup& soup_;
  std::unordered_map<std::array<float, 3>, Index, FloatTripleHash> ids_;
};

PolygonSoup read_binary(const std::string& file, const std::string& bytes) {
  if (bytes.size() < 84)
    throw IoError(file + ": truncated binary STL header (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (84 + 50ull * n != bytes.size())
    throw IoError(file + ": byte 80: binary STL header says " + std::to_string(n) +
                  " triangles but the file holds " + std::to_string((bytes.size() - 84) / 50));
  PolygonSoup soup;
  Welder weld(soup);
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + 84 + 50ull * t + 12;
    std::array<Index, 3> ids;
    for (int k = 0; k < 3; ++k) {
      std::array<float, 3> p;
      std::memcpy(p.data(), rec + 12 * k, 12);
      for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p[i]))
          throw IoError(file + ": byte " + std::to_string(rec - bytes.data() + 12 * k + 4 * i) +
                        ": triangle " + std::to_string(t) + " has a non-finite coordinate");
      ids[k] = weld.vertex(p);
    }
    soup.add_face(ids);
  }
  return soup;
}

// The grammar is fixed (solid, facet normal, outer loop, vertex, endloop, endfacet, endsolid): any other
// word, a facet cut short or a missing endsolid means the file is not what it claims to be.
PolygonSoup read_ascii(const std::string& file, const std::string& bytes) {
  PolygonSoup soup;
  Welder weld(soup);
  std::istringstream in(bytes);
  std::string text;
  int line = 0;
  bool in_solid = false;
  std::vector<Index> corners;
  auto fail = [&](int column, const std::string& what) {
    throw IoError(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
  };
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string word;
    if (!(words >> word)) continue;
    const int column = int(text.find(word)) + 1;
    if (word == "vertex") {
      std::array<float, 3> p;
      if (!(words >> p[0] >> p[1] >> p[2]) || !std::isfinite(p[0]) || !std::isfinite(p[1]) ||
          !std::isfinite(p[2]))
        fail(column + 7, "expected three finite numbers after 'vertex'");
      corners.push_back(weld.vertex(p));
    } else if (word == "endloop") {
      if (corners.size() != 3)
        fail(column, "expected 3 vertices in a facet, found " + std::to_string(corners.size()));
      soup.add_face(corners);
      corners.clear();
    } else if (word == "solid") {
      in_solid = true;
    } else if (word == "endsolid") {
      if (!corners.empty()) fail(column, "expected 'endloop' before 'endsolid'");
      in_solid = false;
    } else if (word != "facet" && word != "outer" && word != "endfacet") {
      fail(column, "expected 'facet', 'outer loop', 'vertex', 'endloop', 'endfacet' or 'endsolid', found '" +
                       word.substr(0, 40) + "'");
    }
  }
  if (in_solid || !corners.empty()) fail(1, "the file ends inside a solid (expected 'endsolid'): truncated?");
  return soup;
}

}  // namespace

bool stl_looks_ascii(const std::string& bytes) {
  if (bytes.compare(0, 5, "solid") != 0) return false;
  // Trust the size formula when it matches.
  if (bytes.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (84 + 50ull * n == bytes.size()) return false;
  }
  return true;
}

PolygonSoup read_stl(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return stl_looks_ascii(bytes) ? read_ascii(path.string(), bytes) : read_binary(path.string(), bytes);
}

}  // namespace nome
