#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/scene/parser.hpp"
#include "nome/scene/scene.hpp"

// Arbitrary bytes as a .slf file: its statements as read_scene reads them (the Tcl they hold is not run: a
// braced value is then refused, located).
NOME_FUZZ_TARGET(slf) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nome::PolygonSoup soup;
  try {
    nome::scene::Diagnostics diagnostics("fuzz.slf");
    nome::scene::SceneAst ast = nome::scene::parse_slf(text, diagnostics);
    diagnostics.throw_if_errors();
    soup = nome::scene::Scene::from_ast(std::move(ast), diagnostics.all()).combined_soup();
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.slf");
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
