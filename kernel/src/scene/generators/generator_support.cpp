#include "scene/generators/generator_support.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "nome/error.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  parser.set_statement_end(row.end_keyword);
  const Token keyword = parser.take();
  GeneratorDecl g;
  g.kind = kind;
  g.name = parser.take_name("a name");
  const Token open = parser.peek();
  parser.expect_symbol("(");
  while (!parser.peek().is_symbol(")") && parser.peek().kind != TokenKind::end)
    g.args.push_back(parser.value());
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

void save(SceneWriter& writer, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  for (const GeneratorDecl& g : writer.ast().generators)
    if (g.kind == kind)
      writer.out() << row.keyword << " " << g.name.text << " ("
                   << writer.values(g.args.data(), int(g.args.size())) << ") " << row.end_keyword << "\n";
}

void declare(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.generators.size(); ++i)
    if (ast.generators[i].kind == kind) out.push_back({&ast.generators[i].name, i});
}

}  // namespace

StatementKind with_generator_syntax(StatementKind kind) {
  kind.parse = parse;
  kind.save = save;
  kind.declare = declare;
  return kind;
}

const std::vector<Value>& generator_arguments(const DefinitionContext& context, Index decl) {
  return context.ast().generators[decl].args;
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

void require(bool is_ok, const char* message) {
  if (!is_ok) throw InvalidInputError(message);
}

}  // namespace nome::scene
