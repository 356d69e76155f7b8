#include <string_view>

#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/scene/scene.hpp"

// Arbitrary bytes as a .nome scene: parsing and evaluation either give a scene or throw nome::Error
// (SceneError with located messages, BudgetError); a scene's soup goes through build and the checks.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nome::PolygonSoup soup;
  try {
    soup = nome::scene::Scene::from_text(text, "fuzz.nome").combined_soup();
  } catch (const nome::Error&) {
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
