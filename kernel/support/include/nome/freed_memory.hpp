#pragma once

namespace nome {

// Keeps the blocks a process frees (up to 32 MB each) for its next allocations instead of handing them
// back to the system. On the machines Nome runs on, faulting in a fresh 4 KB page costs about 10 µs, so a
// slider that rebuilds a 300,000-face sweep spent four times longer faulting pages than computing (issue
// 15's figures). A program calls this first thing in main(); the kernel never changes the allocator by
// itself. Larger blocks are the kernel's Buffers (nome/mesh/buffer.hpp): up to a quarter of the memory
// (2 GB at most) of those is kept too, for the next Buffers of any size.
void keep_freed_memory();

}  // namespace nome
