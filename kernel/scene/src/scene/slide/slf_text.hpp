#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "nome/scene/diagnostic.hpp"

namespace nome::scene {

// A braced Tcl text of a .slf file: a `tclinit { ... }` block or a `{ ... }` value, found at its `{`.
struct SlfBrace {
  SourceLocation at;
  std::string text;  // between the braces, as written
};

// A .slf text with its Tcl cut out. SLIDE hands every braced text to Tcl as written, so it must not be split
// into the statements' tokens: `statements` is the text with each brace's contents blanked (lines and
// columns unchanged, the braces kept), and `braces` holds what was inside, in text order.
struct SlfText {
  std::string statements;
  std::vector<SlfBrace> braces;
};

// Braces nest and a backslash escapes one, as in Tcl; `#` and `(* ... *)` (nested) are comments outside
// them. An unclosed brace is an error at its `{`.
SlfText split_slf_text(std::string_view text, Diagnostics& diagnostics);

}  // namespace nome::scene
