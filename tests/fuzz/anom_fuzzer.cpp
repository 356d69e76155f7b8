#include <string_view>

#include "nome/error.hpp"
#include "nome/scene/parser.hpp"

// Arbitrary bytes as an .anom file (saved slider values and a working mesh): parsing either succeeds
// or reports located errors.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    nome::scene::Diagnostics diagnostics("fuzz.anom");
    nome::scene::parse_anom(text, diagnostics);
    diagnostics.throw_if_errors();
  } catch (const nome::Error&) {
  }
  return 0;
}
