#pragma once

#include <cstddef>
#include <string_view>

#include "nome/scene/diagnostic.hpp"

// Lines and columns of an edited text, as diagnostics count them (1-based; a column counts bytes), and the
// byte offsets an editor's cursor uses.
namespace nome::scene {

// How many lines the text shows (an empty text, or one ending in a newline, has an empty last line).
int line_count(std::string_view text);
// The byte offset of `at`; a line past the end gives the text's end, a column past its line's end gives
// that line's end (before its newline).
std::size_t byte_offset(std::string_view text, SourceLocation at);
// The line and column of a byte offset (clamped to the text's end).
SourceLocation location_at(std::string_view text, std::size_t offset);

}  // namespace nome::scene
