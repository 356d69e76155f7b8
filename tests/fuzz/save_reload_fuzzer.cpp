#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "nome/error.hpp"
#include "nome/mesh/color_attribute.hpp"
#include "nome/scene/save_nome.hpp"
#include "nome/scene/scene.hpp"

namespace {

bool is_same_colors(const nome::PolygonSoup& a, const nome::PolygonSoup& b) {
  for (nome::Index f = 0; f < a.num_faces(); ++f)
    if (nome::face_color(a.face_attributes, f) != nome::face_color(b.face_attributes, f)) return false;
  return true;
}

bool is_same_geometry(const nome::PolygonSoup& a, const nome::PolygonSoup& b) {
  return std::equal(a.positions.begin(), a.positions.end(), b.positions.begin(), b.positions.end()) &&
         std::equal(a.face_offsets.begin(), a.face_offsets.end(), b.face_offsets.begin(),
                    b.face_offsets.end()) &&
         std::equal(a.face_vertices.begin(), a.face_vertices.end(), b.face_vertices.begin(),
                    b.face_vertices.end()) &&
         is_same_colors(a, b);
}

}  // namespace

// Arbitrary bytes as a .nome scene (its deletions and consolidated faces are the user's edits): a scene
// that opens is saved and read back, and the saved text must give the same polygons, bit for bit, and
// save to the same text again.
NOME_FUZZ_TARGET(save_reload) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<nome::scene::Scene> scene;
  try {
    scene = nome::scene::Scene::from_text(text, "fuzz.nome");
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.nome");
    return 0;
  }
  const std::string saved = nome::scene::to_nome_text(*scene);
  nome::scene::Scene reloaded = nome::scene::Scene::from_text(saved, "saved.nome");
  if (!is_same_geometry(scene->combined_soup(), reloaded.combined_soup())) std::abort();
  if (nome::scene::to_nome_text(reloaded) != saved) std::abort();
  return 0;
}
