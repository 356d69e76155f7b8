#include "support/shared_examples.hpp"

#include <filesystem>

namespace nome::test {

std::string shared_examples_dir(const std::string& folder) {
  return std::string(NOME_SOURCE_DIR) + "/../shared/examples/" + folder + "/";
}

bool has_shared_examples(const std::string& folder) {
  return std::filesystem::is_directory(shared_examples_dir(folder));
}

}  // namespace nome::test
