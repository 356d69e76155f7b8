#include "nome/scene/source_text.hpp"

#include <algorithm>

namespace nome::scene {

int line_count(std::string_view text) {
  return 1 + int(std::count(text.begin(), text.end(), '\n'));
}

std::size_t byte_offset(std::string_view text, SourceLocation at) {
  std::size_t start = 0;
  for (int line = 1; line < at.line; ++line) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string_view::npos) return text.size();
    start = newline + 1;
  }
  const std::size_t end = std::min(text.find('\n', start), text.size());
  return std::min(start + std::size_t(std::max(at.column, 1) - 1), end);
}

SourceLocation location_at(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::string_view before = text.substr(0, offset);
  const std::size_t newline = before.rfind('\n');
  const std::size_t start = newline == std::string_view::npos ? 0 : newline + 1;
  return {line_count(before), int(offset - start) + 1};
}

}  // namespace nome::scene
