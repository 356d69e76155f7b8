#include "support/shared_examples.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>

namespace nome::test {
namespace {

std::string shared_dir() {
  const char* dir = std::getenv("NOME_SHARED_DIR");
  if (dir != nullptr && *dir != '\0') return dir;
  return std::string(NOME_SOURCE_DIR) + "/../shared";
}

// One line per test case that reads the shared folder: "<program>\t<test case>". The app's helper threads
// may ask too: the set is guarded.
void record_use() {
  const char* log = std::getenv("NOME_SHARED_USE_LOG");
  if (log == nullptr || *log == '\0') return;
  // Asked outside any test case too (a static list of example files): nothing to record then.
  Catch::IResultCapture* capture = Catch::getCurrentContext().getResultCapture();
  if (capture == nullptr) return;
  const std::string name = capture->getCurrentTestName();
  if (name.empty()) return;
  static std::mutex mutex;
  static std::set<std::string> recorded;
  std::lock_guard lock(mutex);
  if (!recorded.insert(name).second) return;
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  std::ofstream(log, std::ios::app) << program.string() << '\t' << name << '\n';
}

}  // namespace

std::string shared_examples_dir(const std::string& folder) {
  record_use();
  return shared_dir() + "/examples/" + folder + "/";
}

bool has_shared_examples(const std::string& folder) {
  return std::filesystem::is_directory(shared_examples_dir(folder));
}

}  // namespace nome::test
