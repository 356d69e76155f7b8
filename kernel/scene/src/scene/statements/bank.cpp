// `bank NAME set NAME value min max step ... endbank`: sliders.
#include <algorithm>

#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void check_slider(Diagnostics& diagnostics, const std::string& bank, const SliderDecl& s) {
  const std::string full = bank + "_" + s.name.text;
  if (s.min.literal > s.max.literal)
    diagnostics.error(s.min.location, "slider '" + full + "': min " + format_number(s.min.literal) +
                                          " is above max " + format_number(s.max.literal));
  else if (s.value.literal < s.min.literal || s.value.literal > s.max.literal)
    // JIPCAD accepts it, and files rely on it: the value stands until the slider is moved.
    diagnostics.warning(s.value.location,
                        "value " + format_number(s.value.literal) + " of '" + full +
                            "' is outside its slider range [" + format_number(s.min.literal) + ", " +
                            format_number(s.max.literal) + "]: kept until the slider is moved");
  if (!(s.step.literal > 0))
    diagnostics.error(s.step.location,
                      "slider '" + full + "': step must be positive, found " + format_number(s.step.literal));
}

SliderDecl slider(StatementParser& parser, const std::string& bank) {
  parser.set_statement_end({});
  parser.expect_word("set");
  SliderDecl s;
  s.name = parser.take_name("a parameter name");
  s.value = parser.literal_value();
  s.min = parser.literal_value();
  s.max = parser.literal_value();
  s.step = parser.literal_value();
  check_slider(parser.diagnostics(), bank, s);
  return s;
}

// `list (ids)`: the sliders the panel shows. Files list sliders they never set (backface.nom): a warning.
void shown_list(StatementParser& parser, BankDecl& b) {
  parser.set_statement_end({});
  const Token list = parser.take();
  parser.note_dialect(Dialect::jipcad, "'list' in a bank", list.location);
  std::vector<Name> shown = parser.name_list("a slider name or ')'");
  for (const Name& n : shown)
    if (std::none_of(b.sliders.begin(), b.sliders.end(),
                     [&](const SliderDecl& s) { return s.name.text == n.text; }))
      parser.diagnostics().warning(
          n.location, "'" + n.text + "' is not a slider of bank '" + b.name.text + "': not shown");
  if (b.shown) parser.diagnostics().warning(list.location, "second 'list' in bank '" + b.name.text + "'");
  b.shown = std::move(shown);
}

void parse_bank(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  BankDecl b;
  b.name = parser.take_name("a bank name");
  const BlockContext inner{{"set", "list"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    try {
      if (parser.peek().is_word("list"))
        shown_list(parser, b);
      else
        b.sliders.push_back(slider(parser, b.name.text));
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
  parser.ast().banks.push_back(std::move(b));
}

// The sliders' current values, not those of the text that was read.
void save_bank(SceneWriter& writer, Index) {
  const Scene& scene = writer.scene();
  for (const Bank& bank : scene.banks()) {
    writer.out() << "bank " << bank.name << "\n";
    for (ParameterId id : bank.parameters) {
      const Parameter& p = scene.parameters()[id];
      writer.out() << "    set " << p.name << " " << format_number(p.value) << " " << format_number(p.min)
                   << " " << format_number(p.max) << " " << format_number(p.step) << "\n";
    }
    // The successor's banks end with the sliders they show (all of them when the file had no list).
    if (scene.ast().dialect.dialect == Dialect::jipcad) {
      writer.out() << "    list (";
      for (size_t i = 0; i < bank.shown.size(); ++i)
        writer.out() << (i ? " " : "") << scene.parameters()[bank.shown[i]].name;
      writer.out() << ")\n";
    }
    writer.out() << "endbank\n";
  }
}

}  // namespace

StatementKind bank_statement() {
  return {.keyword = "bank", .end_keyword = "endbank", .parse = parse_bank, .save = save_bank};
}

}  // namespace nome::scene
