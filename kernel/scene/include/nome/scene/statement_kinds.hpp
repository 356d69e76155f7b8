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
  bool is_slf = false;  // part of the SLIDE subset read from .slf files
  // Reads the statement at the parser's position (its keyword not yet taken) into the parser's AST.
  void (*parse)(StatementParser& parser, Index kind) = nullptr;
  // Writes every statement of this kind (the writer runs the rows in table order).
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

}  // namespace nome::scene
