#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "nome/scene/ast.hpp"

namespace nome::scene {

// Parses a .nome text (the 2016 language, its save format and the NOME 2.x spellings) into an AST.
// Every syntax error goes to `diagnostics` as `expected X, found Y`; after an error the parser
// resynchronises at the next statement, so one run reports several errors. Names are not resolved here.
// `include [file] endinclude` is resolved relative to the directory of `diagnostics.file()`.
struct ParseOptions {
  std::optional<Dialect> dialect;          // --dialect: overrides what the text's statements say
  std::vector<std::string> include_chain;  // the including files, outermost first (empty: a top file)
};
SceneAst parse_nome(std::string_view text, Diagnostics& diagnostics, const ParseOptions& options = {});

// The line a file saved in the successor's dialect carries, so that it reads back in that dialect even
// when none of its statements tells.
inline constexpr const char* jipcad_header = "# nome-dialect: jipcad";

// A .slf file (Berkeley SLIDE), the subset NOME reads (report 7.1): point, face, object, group and
// `instance TARGET [id NAME] [transforms] endinstance`; surfaces are ignored with a warning, anything else
// is an error `not supported yet: X`. Without top-level instances, the groups no instance uses are the roots.
SceneAst parse_slf(std::string_view text, Diagnostics& diagnostics);

// An .anom file: slider values and a working (consolidated) mesh saved by the 2016 program, applied on
// top of an open scene.
struct AnomAst {
  std::vector<std::pair<Name, double>> saved_parameters;  // `bank_name value`
  std::vector<NamedFace> working_mesh;
};

AnomAst parse_anom(std::string_view text, Diagnostics& diagnostics);

// `cf.tun5.lc5` -> `cf_tun5_lc5`: the one spelling names are compared in.
std::string normalize_name(std::string name);

}  // namespace nome::scene
