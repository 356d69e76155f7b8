#pragma once

#include <vector>

#include "nome/scene/ast.hpp"

namespace nome::scene {

class StatementParser;
class SceneWriter;

// `sharp [weight] [border] (chain) [(chain) ...] endsharp` at the parser's position: one SharpDecl per chain,
// each with the weight. `border` is read only where `can_name_borders` (the top level).
void parse_sharp(StatementParser& parser, std::vector<SharpDecl>& out, bool can_name_borders);
// Writes each declaration as one `sharp ... endsharp` line after `indent`.
void save_sharps(SceneWriter& writer, const std::vector<SharpDecl>& sharps, const char* indent);

}  // namespace nome::scene
