#include <string_view>

#include "fuzz/fuzz_target.hpp"
#include "nome/error.hpp"
#include "nome/scene/parser.hpp"

// Arbitrary bytes as an .anom file (saved slider values and a working mesh): parsing either succeeds
// or reports located errors.
NOME_FUZZ_TARGET(anom) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    nome::scene::Diagnostics diagnostics("fuzz.anom");
    nome::scene::parse_anom(text, diagnostics);
    diagnostics.throw_if_errors();
  } catch (const nome::Error& e) {
    nome::fuzz::require_located_refusal(e, "fuzz.anom");
  }
  return 0;
}
