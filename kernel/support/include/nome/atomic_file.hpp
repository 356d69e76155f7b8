#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

#include "nome/file_blocks.hpp"

namespace nome {

// Writes a file so that it is always either the complete old or the complete new content: the
// writer fills a temporary file in the same folder, which is flushed, synced and renamed over the
// target. On any failure (the writer throws, the disk is full) the temporary file is removed, the
// target is untouched, and IoError is thrown. A process killed mid-save leaves its temporary sibling
// (`NAME.PID.N.tmp`, created exclusively, so unique) behind: nothing reads or reuses it, so correctness
// needs no cleanup; the target is the complete old file (tests/io/atomic_file_kill_test.cpp).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer);

// The same for a writer that fills the file's blocks directly (FileBlocks::room): big meshes, whose
// writers format every byte straight into the block that is written.
void write_file_in_blocks(const std::filesystem::path& path, const std::function<void(FileBlocks&)>& writer);

}  // namespace nome
