#include <string_view>

#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/scene/parser.hpp"
#include "nome/scene/scene.hpp"

// Arbitrary bytes as a .slf file (the SLIDE subset), the way read_scene reads one.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nome::PolygonSoup soup;
  try {
    nome::scene::Diagnostics diagnostics("fuzz.slf");
    nome::scene::SceneAst ast = nome::scene::parse_slf(text, diagnostics);
    diagnostics.throw_if_errors();
    soup = nome::scene::Scene::from_ast(std::move(ast), diagnostics.all()).combined_soup();
  } catch (const nome::Error&) {
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
