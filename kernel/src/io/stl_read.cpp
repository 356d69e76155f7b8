#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unordered_map>

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

bool looks_ascii(const std::string& bytes) {
  if (bytes.compare(0, 5, "solid") != 0) return false;
  // A binary file may also start with "solid": trust the size formula when it matches.
  if (bytes.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (84 + 50ull * n == bytes.size()) return false;
  }
  return true;
}

PolygonSoup read_binary(const std::string& file, const std::string& bytes) {
  if (bytes.size() < 84)
    throw IoError(file + ": truncated binary STL header (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (84 + 50ull * n != bytes.size())
    throw IoError(file + ": binary STL header says " + std::to_string(n) + " triangles but the file holds " +
                  std::to_string((bytes.size() - 84) / 50));
  PolygonSoup soup;
  Welder weld(soup);
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = bytes.data() + 84 + 50ull * t + 12;
    std::array<Index, 3> ids;
    for (int k = 0; k < 3; ++k) {
      std::array<float, 3> p;
      std::memcpy(p.data(), rec + 12 * k, 12);
      ids[k] = weld.vertex(p);
    }
    soup.add_face(ids);
  }
  return soup;
}

PolygonSoup read_ascii(const std::string& file, const std::string& bytes) {
  PolygonSoup soup;
  Welder weld(soup);
  std::istringstream in(bytes);
  std::string text;
  int line = 0;
  std::vector<Index> corners;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string word;
    if (!(words >> word)) continue;
    if (word == "vertex") {
      std::array<float, 3> p;
      if (!(words >> p[0] >> p[1] >> p[2]))
        throw IoError(file + ":" + std::to_string(line) + ":" + std::to_string(text.find("vertex") + 8) +
                      ": expected three numbers after 'vertex'");
      corners.push_back(weld.vertex(p));
    } else if (word == "endloop") {
      if (corners.size() != 3)
        throw IoError(file + ":" + std::to_string(line) + ":1: expected 3 vertices in a facet, found " +
                      std::to_string(corners.size()));
      soup.add_face(corners);
      corners.clear();
    }
  }
  return soup;
}

}  // namespace

PolygonSoup read_stl(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot open");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return looks_ascii(bytes) ? read_ascii(path.string(), bytes) : read_binary(path.string(), bytes);
}

}  // namespace nome
