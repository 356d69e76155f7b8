#pragma once

namespace nome {

// While a slider moves, every stage is rebuilt again and again with arrays of the same sizes. glibc gives
// each block over 32 MB a mapping of its own and unmaps it when it is freed, so each rebuild faults in
// fresh pages that the system zeroes first: a third to a half of a large rebuild's time on these
// machines. keep_freed_memory() has the allocator serve large blocks from its heap and keep what is
// freed there for the next rebuild (a program's choice, made once at its start: the viewer and the
// benchmarks make it); release_freed_memory() gives what is free back to the system, for a program that
// has come to rest. Both do nothing where the C library is not glibc or a sanitizer owns the heap.
void keep_freed_memory();
void release_freed_memory();

}  // namespace nome
