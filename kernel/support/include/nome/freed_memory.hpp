#pragma once

namespace nome {

// Keeps the blocks a process frees (up to 32 MB each) for its next allocations instead of handing them
// back to the system: a slider that rebuilds a large sweep otherwise spends more time faulting in fresh
// pages than computing (`make bench` shows the figures). A program calls this first thing in main(); the
// kernel never changes the allocator by itself. Larger blocks are the kernel's Buffers
// (nome/mesh/buffer.hpp): up to a quarter of the memory (2 GB at most) of those is kept too, for the next
// Buffers of any size.
void keep_freed_memory();

}  // namespace nome
