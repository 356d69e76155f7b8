#include "support/scratch_files.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace nome::test {

std::filesystem::path scratch_path(const std::string& folder, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (folder + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace nome::test
