// `printsetup [fitheight H | fitsize S] [reston flattest | reston FACE] endprintsetup`: the print
// preparation kept with a scene (sizes in model units: mm), which `nome export` and the viewer's export
// apply unless told otherwise. The kernel's print_placement() does the work.
#include <cmath>

#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

double print_setup_number(StatementParser& parser, const char* what, bool is_whole) {
  const Token& t = parser.peek();
  const bool is_usable =
      t.kind == TokenKind::number && std::isfinite(t.number) &&
      (is_whole ? t.number >= 0 && t.number == std::floor(t.number) && t.number < 4e9 : t.number > 0);
  if (!is_usable) parser.fail(t, what);
  return parser.take().number;
}

void parse_print_setup(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  parser.set_statement_end(end);
  PrintPlacementOptions setup;
  while (!parser.peek().is_word(end)) {
    const Token field = parser.peek();
    if (field.is_word("fitheight") || field.is_word("fitsize")) {
      parser.take();
      setup.fit = field.text == "fitheight" ? FitTarget::height : FitTarget::largest;
      setup.fit_size = print_setup_number(parser, "a positive size in mm", false);
    } else if (field.is_word("reston")) {
      parser.take();
      if (parser.peek().is_word("flattest")) {
        parser.take();
        setup.rest = RestOn::flattest;
      } else {
        setup.rest = RestOn::face;
        setup.rest_face = Index(print_setup_number(parser, "flattest or a face number", true));
      }
    } else {
      parser.fail(field, "fitheight, fitsize, reston or " + std::string(end));
    }
  }
  parser.expect_word(end);
  if (parser.ast().print_setup)
    parser.diagnostics().warning(opener.location, "a second printsetup replaces the first");
  parser.ast().print_setup = setup;
}

void save_print_setup(SceneWriter& writer, Index) {
  const std::optional<PrintPlacementOptions>& setup = writer.ast().print_setup;
  if (!setup || setup->is_identity()) return;
  std::ostream& out = writer.out();
  out << "printsetup";
  if (setup->fit != FitTarget::none)
    out << (setup->fit == FitTarget::height ? " fitheight " : " fitsize ") << format_number(setup->fit_size);
  if (setup->rest == RestOn::flattest) out << " reston flattest";
  if (setup->rest == RestOn::face) out << " reston " << setup->rest_face;
  out << " endprintsetup\n";
}

}  // namespace

StatementKind print_setup_statement() {
  return {.keyword = "printsetup",
          .end_keyword = "endprintsetup",
          .parse = parse_print_setup,
          .save = save_print_setup};
}

}  // namespace nome::scene
