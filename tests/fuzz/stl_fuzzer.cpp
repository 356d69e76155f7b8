#include "fuzz/fuzz_file.hpp"
#include "fuzz/mesh_checks.hpp"
#include "nome/error.hpp"
#include "nome/io/stl.hpp"

// Arbitrary bytes as a .stl file (ASCII or binary): read_stl either returns a soup or throws nome::Error.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  nome::PolygonSoup soup;
  try {
    soup = nome::read_stl(nome::fuzz::input_file(data, size, ".stl"));
  } catch (const nome::Error&) {
    return 0;
  }
  nome::fuzz::build_and_check(std::move(soup));
  return 0;
}
