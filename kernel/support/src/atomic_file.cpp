#include "nome/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>

#include "nome/error.hpp"
#include "nome/file_blocks.hpp"

namespace nome {
namespace {

// Created exclusively, so two writers (threads or processes) never share one; a writer killed before
// its rename leaves this sibling behind, which no later save reads or reuses. Returned open for writing.
struct TemporarySibling {
  std::filesystem::path path;
  int fd = -1;
};

TemporarySibling temporary_sibling(const std::filesystem::path& path) {
  std::random_device seed;
  for (;;) {
    std::filesystem::path tmp = path;
    tmp += "." + std::to_string(::getpid()) + "." + std::to_string(seed() % 1000000) + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {tmp, fd};
    if (errno != EEXIST) throw IoError(path.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
}

void sync_path(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

// Fills a temporary sibling through FileBlocks, syncs it and renames it over `path`.
void write_file_in_blocks(const std::filesystem::path& path, const std::function<void(FileBlocks&)>& fill) {
  const auto [tmp, fd] = temporary_sibling(path);
  try {
    int error = 0;
    try {
      FileBlocks blocks(fd);
      fill(blocks);
      error = blocks.finish();
      if (error == 0 && ::fsync(fd) != 0) error = errno;
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
    if (error != 0) throw IoError(path.string() + ": write failed (" + std::strerror(error) + ")");
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw IoError(path.string() + ": cannot replace (" + ec.message() + ")");
    // The rename itself is durable only once the folder is synced.
    sync_path(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer) {
  write_file_in_blocks(path, [&](FileBlocks& blocks) {
    std::ostream out(&blocks);
    writer(out);
  });
}

}  // namespace nome
