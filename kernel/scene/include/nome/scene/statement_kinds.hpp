#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nome/scene/ast.hpp"
#include "nome/scene/piece.hpp"

namespace nome::scene {

// Internal to the kernel (kernel/scene/src/): the parser, the writer and the evaluators' view of a scene.
class StatementParser;
class SceneWriter;
class DefinitionScope;
class DefinitionContext;
struct SampledCurve;

// A definition as the names table sees it: its name and where the kind keeps it.
struct DeclaredName {
  const Name* name;
  Index decl;
};

// The texts a statement belongs to. Both .nome dialects read the statements of either (`--dialect 2016`
// reads a sphere too), so one the successor alone has tells a file's dialect: the first such decides it.
enum class StatementDialect {
  slide,                // SLIDE's subset read from .slf files, and every .nome file
  nome,                 // every .nome file, the 2016 report's or the successor's
  successor,            // JIPCAD's: it makes a .nome file the successor's; a .slf file refuses it
  slide_only,           // SLIDE's own (its Tcl, its render statement): only .slf files
  successor_and_slide,  // JIPCAD's in a .nome file (a cue, as `successor`), and SLIDE's too (camera, light)
};

// Whether a .slf file reads the statement, and whether a .nome file does.
bool is_slide_statement(StatementDialect dialect);
bool is_nome_statement(StatementDialect dialect);

// One top-level statement of the .nome language: how it is parsed, saved and, for a definition that makes
// geometry, evaluated. The parser, the writer and the scene read this table only, so that adding a
// generator is its evaluator file and one row (see statement_kinds.cpp).
struct StatementKind {
  std::string_view keyword = {};
  std::string_view end_keyword = {};              // the word that closes it (a block: `endmesh`, `endbank`)
  std::string_view alternative_end_keyword = {};  // accepted too (the report's tunnels close with endfunnel)
  // Generators: `keyword NAME (arguments) end_keyword` with one of two argument counts.
  std::string_view signature = {};
  std::size_t argument_count = 0;
  std::size_t alternative_argument_count = 0;
  StatementDialect dialect = StatementDialect::nome;
  // Reads the statement at the parser's position (its keyword not yet taken) into the parser's AST.
  void (*parse)(StatementParser& parser, Index kind) = nullptr;
  // Writes every statement of this kind (the writer runs the rows in table order). Null for a row whose
  // statements another row writes (SLIDE's mirror node is a group).
  void (*save)(SceneWriter& writer, Index kind) = nullptr;
  // Definitions only: the names this kind defines, and the geometry of one of them.
  void (*declare)(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) = nullptr;
  Piece (*evaluate)(DefinitionContext& context, Index decl) = nullptr;
  // Optional, for a generator that tells its topology cheaply (a sweep): evaluate()'s positions alone, with
  // the topology key its piece would carry. When the key is the last piece's, the scene keeps that piece's
  // faces and names and moves its vertices (a slider tick makes no names).
  PiecePositions (*evaluate_positions)(DefinitionContext& context, Index decl) = nullptr;
  // The vertex-name lists a definition reads: a name that is not a point copies another placement's vertex,
  // which must then be evaluated first. Null: the definition makes its own vertices.
  void (*vertex_lists)(const DefinitionScope& scope, Index decl,
                       std::vector<const std::vector<Name>*>& out) = nullptr;
  // Curves only (polyline, circle, beziercurve, bspline): the points a sweep takes as its path or
  // cross-section (scene/curves.hpp).
  SampledCurve (*sample)(DefinitionContext& context, Index decl) = nullptr;
  // What follows `keyword NAME` in a smallest working definition, given points p0 p1 p2 p3 and a top-level
  // face pf (p0 p1 p2): the registry test round-trips it.
  std::string_view example = {};

  bool is_definition() const { return declare != nullptr; }
  bool makes_geometry() const { return evaluate != nullptr; }
};

// Every statement, in the order the parser lists them and the writer writes them.
std::span<const StatementKind> statement_kinds();
// The row of `keyword`, if it starts a statement.
std::optional<Index> find_statement_kind(std::string_view keyword);
// `bank, surface, point, ...`: the keywords of the rows, comma separated (the SLIDE subset if `is_slf`).
std::string statement_keyword_list(bool is_slf = false);

// A row added after the built-in ones for as long as this lives: a statement kept outside the kernel is its
// own file and this one line. Added and removed in nested order, while no text is being read.
class AddedStatementKind {
 public:
  explicit AddedStatementKind(StatementKind kind);
  ~AddedStatementKind();
  AddedStatementKind(const AddedStatementKind&) = delete;
  AddedStatementKind& operator=(const AddedStatementKind&) = delete;
};

// A generator's row completed with what all generators share: `keyword NAME (arguments) end_keyword`
// parsed with the row's argument counts and signature, saved as written, named in the definitions.
StatementKind with_generator_syntax(StatementKind kind);
// The values of generator `decl`'s arguments now, each slider read recorded (its evaluator's numbers).
std::vector<double> generator_numbers(DefinitionContext& context, Index decl);

}  // namespace nome::scene
