// `include [file.nom] endinclude` or `include file.nom endinclude` (the successor's): the file's statements
// as if written here. The path is relative to the including file; included files may include others, and a
// cycle is refused with its chain. SLIDE writes `include "file.slf"`.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// The bracketed path: its tokens joined back (a path has no spaces; `../a.nom` is several tokens).
std::string bracketed_path(StatementParser& parser) {
  parser.expect_symbol("[");
  std::string path;
  while (!parser.peek().is_symbol("]")) {
    const Token& t = parser.peek();
    if (t.kind == TokenKind::end || t.is_word("endinclude")) parser.fail(t, "']' closing the file name");
    path += t.kind == TokenKind::parameter ? "$" + t.text : t.text;
    parser.take();
  }
  parser.take();
  if (path.empty()) parser.fail(parser.peek(), "a file name between '[' and ']'");
  return path;
}

std::string chain_text(const std::vector<std::string>& chain, const std::string& last) {
  std::string text;
  for (const std::string& f : chain) text += f + " -> ";
  return text + last;
}

void read_included(StatementParser& parser, const Token& at, const std::string& written) {
  const std::vector<std::string>& chain = parser.include_chain();
  const std::filesystem::path base = std::filesystem::path(chain.back()).parent_path();
  const std::filesystem::path path = (base / written).lexically_normal();
  const auto same_file = [&](const std::string& f) {
    std::error_code error;
    return std::filesystem::equivalent(f, path, error);
  };
  if (std::any_of(chain.begin(), chain.end(), same_file)) {
    parser.diagnostics().error(
        at.location, "include cycle: " + chain_text(chain, path.string()) + " is already being read");
    return;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    parser.diagnostics().error(at.location, "cannot read included file '" + path.string() + "'");
    return;
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::vector<std::string> inner_chain = chain;
  inner_chain.push_back(path.string());
  Diagnostics inner(path.string());
  if (parser.is_slf()) {
    SlfText split = split_slf_text(text.str(), inner);
    StatementParser included(split.statements, inner, parser, inner_chain);
    included.set_slf_braces(std::move(split.braces));
    included.parse_statements();
  } else {
    StatementParser(text.str(), inner, parser, inner_chain).parse_statements();
  }
  for (const Diagnostic& d : inner.all()) parser.diagnostics().add(d);
  parser.ast().included_files.push_back(path.string());
}

void parse_include(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  // SLIDE's: `include "file.slf"`, no end word.
  if (parser.is_slf()) {
    read_included(parser, opener, parser.quoted_text("a file name in quotes"));
    return;
  }
  parser.set_statement_end(end);
  // JIPCAD's grammar also takes the name as one identifier (`include z_inclSurfaces.nom endinclude`: '.'
  // is an identifier character), as its tutorials write it.
  std::string written;
  if (parser.peek().kind == TokenKind::word && !parser.peek().is_word(end)) {
    written = parser.take().text;
  } else {
    if (!parser.peek().is_symbol("[")) parser.fail(parser.peek(), "'[' or a file name");
    written = bracketed_path(parser);
  }
  parser.expect_word(end);
  read_included(parser, opener, written);
}

// The included statements are saved with the scene's own (the writer writes one self-contained file).
void save_include(SceneWriter&, Index) {}

}  // namespace

StatementKind include_statement() {
  return {.keyword = "include",
          .end_keyword = "endinclude",
          .dialect = StatementDialect::successor_and_slide,
          .parse = parse_include,
          .save = save_include};
}

}  // namespace nome::scene
