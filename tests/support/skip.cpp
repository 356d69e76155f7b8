#include "support/skip.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace nome::test {

bool skips_fail() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && *ci != '\0' && std::string(ci) != "0" && std::string(ci) != "false";
}

void record_skip(const std::string& reason) {
  const char* log = std::getenv("NOME_SKIP_LOG");
  if (log == nullptr || *log == '\0') return;
  // One short line in append mode: the parallel test processes' lines do not interleave.
  std::ofstream(log, std::ios::app) << Catch::getResultCapture().getCurrentTestName() << ": " << reason
                                    << '\n';
}

}  // namespace nome::test
