#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

// The readers take a path (they report `file:line:col`), so each fuzz input is written to a file of the
// right extension first: one per process, in memory when /dev/shm exists.
namespace nome::fuzz {

inline std::filesystem::path input_file(const uint8_t* data, size_t size, const std::string& extension) {
  static const std::filesystem::path path =
      (std::filesystem::exists("/dev/shm") ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path()) /
      ("nome_fuzz_" + std::to_string(::getpid()) + extension);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), size);
  return path;
}

}  // namespace nome::fuzz
