#include "nome/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>

#include "nome/error.hpp"

namespace nome {
namespace {

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  std::random_device seed;
  std::filesystem::path tmp = path;
  tmp += "." + std::to_string(::getpid()) + "." + std::to_string(seed() % 1000000) + ".tmp";
  return tmp;
}

void sync_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer) {
  const std::filesystem::path tmp = temporary_sibling(path);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw IoError(path.string() + ": cannot write (" + std::strerror(errno) + ")");
      writer(out);
      out.flush();
      if (!out) throw IoError(path.string() + ": write failed (disk full?)");
    }
    sync_file(tmp);
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw IoError(path.string() + ": cannot replace (" + ec.message() + ")");
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace nome
