#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <streambuf>
#include <thread>
#include <vector>

#include "nome/buffer.hpp"

namespace nome {

// The bytes of an open file, gathered into large blocks that a second thread writes (one write(2) per
// block) while the caller fills the next, starting the disk's write-back as it goes so that the final
// sync waits only for the last blocks (the export of a big mesh to disk takes about as long as writing
// its bytes); where threads cannot start (can_start_threads), the caller writes each block when full.
// Writers fill blocks directly (room/commit: every byte written once), or use it as the
// streambuf of a std::ostream. write_file_atomically makes one over its temporary file.
class FileBlocks : public std::streambuf {
 public:
  static constexpr std::size_t block_bytes = std::size_t(4) << 20;
  // The most room() gives: a block starts with up to a disk block's bytes carried over from the last.
  static constexpr std::size_t max_room = block_bytes / 2;

  explicit FileBlocks(int fd);
  ~FileBlocks() override;  // stops the writer thread; whatever was not finished is left unwritten
  FileBlocks(const FileBlocks&) = delete;
  FileBlocks& operator=(const FileBlocks&) = delete;

  // Where the next `bytes` (at most max_room) go; commit(end) once they are written up to `end`.
  char* room(std::size_t bytes) {
    if (std::size_t(epptr() - pptr()) < bytes) hand_over();
    return pptr();
  }
  void commit(char* end) { pbump(int(end - pptr())); }

  // Writes what is left and waits for the writer thread. Returns 0, or the errno of the first failed
  // write; nothing can be written afterwards.
  int finish();

 protected:
  int_type overflow(int_type c) override;

 private:
  void hand_over();
  void write_through();
  void write_blocks();
  void write_block(const Buffer<char>& block, std::size_t bytes);
  void stop();
  void end_direct();

  int fd_;
  std::atomic<bool> direct_;  // the file is open with O_DIRECT: blocks are written in whole units
  const bool is_threaded_;    // a writer thread writes the full blocks
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Buffer<char>> blocks_;
  std::vector<std::size_t> free_;                         // blocks the caller may fill
  std::deque<std::pair<std::size_t, std::size_t>> full_;  // (block, bytes) in file order
  std::size_t filling_ = 0;
  bool done_ = false;
  int error_ = 0;
  std::size_t written_ = 0, write_back_from_ = 0;  // file offsets: bytes written, start of unsynced range
  std::thread writer_;
};

}  // namespace nome
