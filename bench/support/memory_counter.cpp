#include "support/memory_counter.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace {

// A field of /proc/self/status in bytes (its values are in kB).
std::size_t status_bytes(const char* field) {
  std::ifstream status("/proc/self/status");
  const std::size_t length = std::strlen(field);
  for (std::string line; std::getline(status, line);)
    if (line.compare(0, length, field) == 0) return std::stoul(line.substr(length)) * 1024;
  return 0;
}

std::size_t base = 0;

}  // namespace

namespace nome::bench {

void reset_peak() {
  // Writing 5 to clear_refs sets the process's peak resident size back to its current one.
  if (FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
    std::fputs("5", f);
    std::fclose(f);
  }
  base = status_bytes("VmRSS:");
}

std::size_t peak_bytes_since_reset() {
  const std::size_t peak = status_bytes("VmHWM:");
  return peak > base ? peak - base : 0;
}

}  // namespace nome::bench
