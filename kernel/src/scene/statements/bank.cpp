// `bank NAME set NAME value min max step ... endbank`: sliders.
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
    diagnostics.error(s.value.location, "value " + format_number(s.value.literal) + " of '" + full +
                                            "' is outside its slider range [" + format_number(s.min.literal) +
                                            ", " + format_number(s.max.literal) + "]");
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

void parse(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  BankDecl b;
  b.name = parser.take_name("a bank name");
  const BlockContext inner{{"set"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    try {
      b.sliders.push_back(slider(parser, b.name.text));
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
  parser.ast().banks.push_back(std::move(b));
}

// The sliders' current values, not those of the text that was read.
void save(SceneWriter& writer, Index) {
  const Scene& scene = writer.scene();
  for (const Bank& bank : scene.banks()) {
    writer.out() << "bank " << bank.name << "\n";
    for (Index id : bank.parameters) {
      const Parameter& p = scene.parameters()[id];
      writer.out() << "    set " << p.name << " " << format_number(p.value) << " " << format_number(p.min)
                   << " " << format_number(p.max) << " " << format_number(p.step) << "\n";
    }
    writer.out() << "endbank\n";
  }
}

}  // namespace

StatementKind bank_statement() {
  return {.keyword = "bank", .end_keyword = "endbank", .parse = parse, .save = save};
}

}  // namespace nome::scene
