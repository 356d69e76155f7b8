#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/scene/scene.hpp"

// Arbitrary bytes as a .nome scene: parsing and evaluation either give a scene or throw nome::Error
// (SceneError with located messages, BudgetError); a scene's soup goes through build and the checks.
NOME_FUZZ_TARGET(nome) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nome::PolygonSoup soup;
  try {
    soup = nome::scene::Scene::from_text(text, "fuzz.nome").combined_soup();
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.nome");
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
