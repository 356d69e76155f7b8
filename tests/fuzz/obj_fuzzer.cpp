#include "fuzz/fuzz_file.hpp"
#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/io/obj.hpp"

// Arbitrary bytes as a .obj file: read_obj either returns a soup or throws nome::Error.
NOME_FUZZ_TARGET(obj) {
  const std::filesystem::path file = nome::fuzz::input_file(data, size, ".obj");
  nome::PolygonSoup soup;
  try {
    soup = nome::read_obj(file);
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, file.string());
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
