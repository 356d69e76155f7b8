#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/io/sif.hpp"

// Arbitrary bytes as a .sif file, with and without triangle pairing (the first byte chooses).
NOME_FUZZ_TARGET(sif) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  nome::SifOptions options;
  options.pair_triangles = data[0] & 1;
  nome::PolygonSoup soup;
  try {
    soup = nome::parse_sif(text, "fuzz.sif", options);
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.sif");
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
