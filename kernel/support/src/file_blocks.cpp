#include "nome/file_blocks.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "nome/thread_support.hpp"

namespace nome {
namespace {

// Three blocks: one filling, one being written, one ready, so neither side waits while the other keeps up.
constexpr std::size_t num_blocks = 3;
// Write-back is started for every this many bytes written (ignored where the file system has none, as
// on tmpfs): the disk works while the mesh is still being formatted.
constexpr std::size_t write_back_bytes = std::size_t(16) << 20;
// Direct writes (O_DIRECT) need offsets and lengths in multiples of the device's block, at most this.
constexpr std::size_t direct_unit = 4096;

// Direct writes skip the page cache, whose pages cost as much as the writing on these machines (fresh
// memory, see buffer.hpp); refused by some file systems, which then get ordinary writes.
bool start_direct(int fd) {
  const int flags = ::fcntl(fd, F_GETFL);
  return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_DIRECT) == 0;
}

}  // namespace

// The other blocks and the writer thread come with the first full block: a small file is written by
// this thread from one block.
FileBlocks::FileBlocks(int fd)
    : fd_(fd), direct_(start_direct(fd)), is_threaded_(can_start_threads()), blocks_(num_blocks) {
  for (std::size_t b = 1; b < num_blocks; ++b) free_.push_back(b);
  blocks_[0].resize(block_bytes);
  setp(blocks_[0].data(), blocks_[0].data() + block_bytes);
}

FileBlocks::~FileBlocks() {
  stop();
}

void FileBlocks::stop() {
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  changed_.notify_all();
  if (writer_.joinable()) writer_.join();
}

// A direct write takes whole units: the bytes after the last one move on to the next block.
void FileBlocks::hand_over() {
  if (!is_threaded_) return write_through();
  if (!writer_.joinable()) writer_ = std::thread([this] { write_blocks(); });
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !free_.empty(); });
  const std::size_t next = free_.back();
  free_.pop_back();
  if (blocks_[next].empty()) blocks_[next].resize(block_bytes);  // no other thread has seen this block
  const std::size_t bytes = std::size_t(pptr() - pbase());
  const std::size_t kept = direct_ ? bytes % direct_unit : 0;
  std::memcpy(blocks_[next].data(), pptr() - kept, kept);
  full_.emplace_back(filling_, bytes - kept);
  changed_.notify_all();
  filling_ = next;
  setp(blocks_[filling_].data(), blocks_[filling_].data() + block_bytes);
  pbump(int(kept));
}

// Without a writer thread the full block is written at once, the bytes a direct write leaves moved to its
// start: the same writes as the writer thread's.
void FileBlocks::write_through() {
  const std::size_t bytes = std::size_t(pptr() - pbase());
  const std::size_t kept = direct_ ? bytes % direct_unit : 0;
  write_block(blocks_[filling_], bytes - kept);
  std::memmove(blocks_[filling_].data(), pptr() - kept, kept);
  setp(blocks_[filling_].data(), blocks_[filling_].data() + block_bytes);
  pbump(int(kept));
}

FileBlocks::int_type FileBlocks::overflow(int_type c) {
  hand_over();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int FileBlocks::finish() {
  const std::size_t bytes = std::size_t(pptr() - pbase());
  setp(nullptr, nullptr);
  if (!writer_.joinable()) {
    write_block(blocks_[filling_], bytes);
    return error_;
  }
  {
    const std::lock_guard lock(mutex_);
    full_.emplace_back(filling_, bytes);
  }
  stop();
  return error_;
}

void FileBlocks::write_blocks() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return done_ || !full_.empty(); });
    if (full_.empty()) return;
    const auto [block, bytes] = full_.front();
    full_.pop_front();
    lock.unlock();
    write_block(blocks_[block], bytes);
    lock.lock();
    free_.push_back(block);
    changed_.notify_all();
  }
}

// After a failed write the rest is dropped: finish() reports the first error.
void FileBlocks::write_block(const Buffer<char>& block, std::size_t bytes) {
  if (direct_ && bytes % direct_unit != 0) end_direct();  // the file's last block
  for (std::size_t at = 0; at < bytes && error_ == 0;) {
    const ssize_t n = ::write(fd_, block.data() + at, bytes - at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EINVAL && direct_) {  // a device whose block is larger than direct_unit
      end_direct();
      continue;
    }
    if (n <= 0) {
      error_ = n < 0 ? errno : ENOSPC;
      return;
    }
    at += std::size_t(n);
    written_ += std::size_t(n);
  }
  if (direct_ || written_ - write_back_from_ < write_back_bytes) return;
#ifndef __EMSCRIPTEN__  // the browser's files are in memory: no disk to start, and no sync_file_range
  ::sync_file_range(fd_, off64_t(write_back_from_), off64_t(written_ - write_back_from_),
                    SYNC_FILE_RANGE_WRITE);
#endif
  write_back_from_ = written_;
}

void FileBlocks::end_direct() {
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_DIRECT);
  direct_ = false;
}

}  // namespace nome
