#include "scene/generators/generator_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "nome/error.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// `[ ... ]` after a function keyword: the text between the brackets, rebuilt from its tokens.
FunctionText function_text(StatementParser& parser) {
  FunctionText f;
  f.keyword = parser.take_name("a function keyword");
  f.location = parser.peek().location;
  parser.expect_symbol("[");
  bool is_after_atom = false;
  while (!parser.peek().is_symbol("]") && parser.peek().kind != TokenKind::end) {
    const Token t = parser.take();
    // Two words or numbers in a row stay apart (`5 x` is not `5x`).
    const bool is_atom = t.kind != TokenKind::symbol;
    if (is_after_atom && is_atom) f.text += ' ';
    f.text += (t.kind == TokenKind::parameter ? "$" : "") + t.text;
    is_after_atom = is_atom;
  }
  parser.expect_symbol("]");
  return f;
}

// A word among the arguments is an option the row's signature names (`[botcap]`), a function keyword
// before the arguments one it names (`func [f(x,y)]`).
bool is_in_signature(const StatementKind& row, const std::string& word) {
  return row.signature.find(word) != std::string_view::npos;
}

void parse_generator_support(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  parser.set_statement_end(row.end_keyword);
  const Token keyword = parser.take();
  GeneratorDecl g;
  g.kind = kind;
  g.name = parser.take_name("a name");
  while (parser.peek().kind == TokenKind::word && parser.peek(1).is_symbol("[") &&
         is_in_signature(row, parser.peek().text + " ["))
    g.functions.push_back(function_text(parser));
  const Token open = parser.peek();
  parser.expect_symbol("(");
  while (!parser.peek().is_symbol(")") && parser.peek().kind != TokenKind::end) {
    if (parser.peek().kind == TokenKind::word && is_in_signature(row, "[" + parser.peek().text + "]"))
      g.options.push_back(parser.take_name("an option"));
    else
      g.args.push_back(parser.value());
  }
  parser.expect_symbol(")");
  // No alternative count (0) must not let an empty list through: the evaluator reads its arguments.
  const bool is_alternative =
      row.alternative_argument_count != 0 && g.args.size() == row.alternative_argument_count;
  if (g.args.size() != row.argument_count && !is_alternative)
    parser.diagnostics().error(open.location, keyword.text + " '" + g.name.text + "' takes " +
                                                  std::to_string(row.argument_count) + " arguments " +
                                                  std::string(row.signature) + ", found " +
                                                  std::to_string(g.args.size()));
  if (!row.alternative_end_keyword.empty() && parser.peek().is_word(row.alternative_end_keyword))
    parser.take();
  else
    parser.expect_word(row.end_keyword);
  parser.ast().generators.push_back(std::move(g));
}

void save_generator_support(SceneWriter& writer, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  for (const GeneratorDecl& g : writer.ast().generators)
    if (g.kind == kind) {
      writer.out() << row.keyword << " " << g.name.text;
      for (const FunctionText& f : g.functions)
        writer.out() << " " << f.keyword.text << " [" << f.text << "]";
      writer.out() << " (" << writer.values(g.args.data(), int(g.args.size()));
      for (const Name& option : g.options) writer.out() << " " << option.text;
      writer.out() << ") " << row.end_keyword << "\n";
    }
}

void declare_generator_support(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.generators.size(); ++i)
    if (ast.generators[i].kind == kind) out.push_back({&ast.generators[i].name, i});
}

}  // namespace

StatementKind with_generator_syntax(StatementKind kind) {
  kind.parse = parse_generator_support;
  kind.save = save_generator_support;
  kind.declare = declare_generator_support;
  return kind;
}

const std::vector<Value>& generator_arguments(const DefinitionContext& context, Index decl) {
  return context.ast().generators[decl].args;
}

void expect_generator_faces(const DefinitionContext& context, Index decl, double faces) {
  const GeneratorDecl& g = context.ast().generators[decl];
  context.expect_faces(g.name.location,
                       std::string(statement_kinds()[g.kind].keyword) + " '" + g.name.text + "'", faces);
}

std::vector<double> generator_numbers(DefinitionContext& context, Index decl) {
  std::vector<double> numbers;
  for (const Value& v : generator_arguments(context, decl)) numbers.push_back(context.number(v));
  return numbers;
}

Index ring(Piece& piece, int n, double radius, double z, const char* prefix) {
  const Index first = piece.soup.num_vertices();
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    piece.add_vertex({radius * std::cos(a), radius * std::sin(a), z}, prefix + std::to_string(i));
  }
  return first;
}

void band(Piece& piece, int n, Index lower, Index upper, const char* prefix) {
  for (int i = 0; i < n; ++i) {
    const Index j = Index((i + 1) % n);
    const std::array<Index, 4> quad{lower + Index(i), lower + j, upper + j, upper + Index(i)};
    piece.add_face(quad, prefix + std::to_string(i));
  }
}

std::vector<bool> generator_options(const DefinitionContext& context, Index decl,
                                    std::initializer_list<std::string_view> known) {
  std::vector<bool> present(known.size(), false);
  for (const Name& option : context.ast().generators[decl].options) {
    const auto it = std::find(known.begin(), known.end(), option.text);
    if (it == known.end()) throw EvaluationError(option.location, "unknown option '" + option.text + "'");
    present[size_t(it - known.begin())] = true;
  }
  return present;
}

std::vector<const FunctionText*> generator_functions(const DefinitionContext& context, Index decl,
                                                     std::initializer_list<std::string_view> keywords) {
  const GeneratorDecl& g = context.ast().generators[decl];
  std::vector<const FunctionText*> found(keywords.size(), nullptr);
  for (const FunctionText& f : g.functions) {
    const auto it = std::find(keywords.begin(), keywords.end(), f.keyword.text);
    if (it == keywords.end() || found[size_t(it - keywords.begin())])
      throw EvaluationError(f.keyword.location, "unexpected '" + f.keyword.text + "'");
    found[size_t(it - keywords.begin())] = &f;
  }
  for (size_t i = 0; i < found.size(); ++i)
    if (!found[i])
      throw EvaluationError(g.name.location,
                            g.name.text + " needs '" + std::string(keywords.begin()[i]) + " [...]'");
  return found;
}

double number_in(DefinitionContext& context, const Value& v, double lo, double hi, const char* what) {
  const double x = context.number(v);
  if (!(x >= lo && x <= hi))
    throw EvaluationError(v.location, std::string(what) + " must be in [" + format_number(lo) + ", " +
                                          format_number(hi) + "], found " + format_number(x));
  return x;
}

double non_negative(DefinitionContext& context, const Value& v, const char* what) {
  const double x = context.number(v);
  if (!(x >= 0))
    throw EvaluationError(v.location, std::string(what) + " must not be negative, found " + format_number(x));
  return x;
}

double sweep_degrees(DefinitionContext& context, const Value& v, const char* what) {
  const double x = context.number(v);
  if (!(x > 0 && x <= 360))
    throw EvaluationError(v.location,
                          std::string(what) + " must be in (0, 360] degrees, found " + format_number(x));
  return x;
}

void require(bool is_ok, const char* message) {
  if (!is_ok) throw InvalidInputError(message);
}

}  // namespace nome::scene
