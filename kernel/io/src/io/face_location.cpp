#include "nome/io/face_location.hpp"

#include <cctype>
#include <fstream>
#include <iterator>
#include <sstream>

#include "io/stl_detect.hpp"
#include "nome/io/file_extension.hpp"

namespace nome {
namespace {

// The `count`-th line (from 0) whose first word is `keyword`, as `line:col`; empty when there are fewer.
std::string nth_keyword_line(std::istream& in, const std::string& keyword, Index count) {
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    const size_t start = text.find_first_not_of(" \t");
    if (start == std::string::npos || text.compare(start, keyword.size(), keyword) != 0) continue;
    const size_t end = start + keyword.size();
    if (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) continue;
    if (count-- == 0) return std::to_string(line) + ":" + std::to_string(start + 1);
  }
  return {};
}

}  // namespace

std::string locate_face_in_file(const std::filesystem::path& path, Index face) {
  const std::string ext = lower_extension(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::string where;
  if (ext == ".obj") {
    where = nth_keyword_line(in, "f", face);
  } else if (ext == ".stl") {
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!stl_looks_ascii(bytes)) {
      const size_t offset = 84 + 50 * size_t(face);
      return offset < bytes.size() ? path.string() + ": byte " + std::to_string(offset) : std::string();
    }
    std::istringstream text(bytes);
    where = nth_keyword_line(text, "facet", face);
  }
  return where.empty() ? where : path.string() + ":" + where;
}

}  // namespace nome
