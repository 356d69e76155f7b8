#include "nome/error.hpp"
#include "nome/io/three_mf.hpp"

// lib3mf has no browser build; the page says 3MF is the desktop's, and a 3MF file is refused by name.
namespace nome {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path) {
  throw IoError(
      path.string() +
      ": 3MF needs lib3mf, which the browser build does not have; use .stl, .obj, .ply or .glb here, "
      "or the desktop nome for 3MF");
}

}  // namespace

void write_3mf(const std::filesystem::path& path, const Mesh&, const ThreeMfOptions&) {
  refuse(path);
}

ThreeMfModel read_3mf(const std::filesystem::path& path) {
  refuse(path);
}

}  // namespace nome
