#include "nome/scene/source_place.hpp"

#include <algorithm>
#include <charconv>

#include "nome/mesh/input_faces.hpp"

namespace nome::scene {
namespace {

// The positive number of the digits at `at`, and where they end; none when there are no digits.
std::optional<int> read_number(std::string_view text, std::size_t& at) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data() + at, text.data() + text.size(), value);
  if (error != std::errc() || value <= 0) return std::nullopt;
  at = std::size_t(end - text.data());
  return value;
}

}  // namespace

std::optional<SourcePlace> parse_source_place(std::string_view text) {
  for (std::size_t colon = text.find(':'); colon != std::string_view::npos;
       colon = text.find(':', colon + 1)) {
    if (colon == 0) continue;
    std::size_t at = colon + 1;
    const std::optional<int> line = read_number(text, at);
    if (!line || at >= text.size() || text[at] != ':') continue;
    ++at;
    const std::optional<int> column = read_number(text, at);
    if (!column || (at < text.size() && text[at] != ':')) continue;
    return SourcePlace{std::string(text.substr(0, colon)), {*line, *column}};
  }
  return std::nullopt;
}

std::optional<SourcePlace> face_statement(const PolygonSoup& soup, Index face) {
  if (face >= soup.num_faces()) return std::nullopt;
  return parse_source_place(soup.origin(face));
}

std::optional<SourcePlace> shown_face_statement(const Mesh& shown, const PolygonSoup& soup, Index face) {
  if (face >= shown.num_faces()) return std::nullopt;
  if (shown.face_attributes().find<Index>(input_face_attribute)) {
    const std::optional<Index> input = input_face(shown, face);
    return input ? face_statement(soup, *input) : std::nullopt;
  }
  return face_statement(soup, face);
}

std::optional<SourcePlace> vertex_statement(const Mesh& shown, const PolygonSoup& soup, Index vertex) {
  if (vertex >= shown.num_vertices()) return std::nullopt;
  Index first = no_index;
  for (Index corner : shown.vertex_corners(vertex)) first = std::min(first, shown.corner_face(corner));
  if (first == no_index) return std::nullopt;
  return shown_face_statement(shown, soup, first);
}

}  // namespace nome::scene
