#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/scene/scene.hpp"
#include "support/funnel_cube_scene.hpp"

// Arbitrary bytes as an .anom file applied to the funnel cube: either a located refusal (the scene then
// keeps its geometry) or slider values and a working mesh whose soup goes through build and the checks.
NOME_FUZZ_TARGET(anom_scene) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  nome::scene::Scene scene = nome::scene::Scene::from_text(nome::test::funnel_cube_scene, "fuzz.nome");
  try {
    scene.apply_anom(text, "fuzz.anom");
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.anom");
  }
  nome::fuzz::build_and_check(scene.combined_soup());
  return 0;
}
