#pragma once

#include <cstddef>

// Heap bytes live and their peak, counted by this executable's replacement operator new/delete.
namespace nome::bench {

std::size_t live_bytes();
// Starts a new peak measurement from the bytes live now.
void reset_peak();
// The highest live byte count since reset_peak(), minus the bytes live at that reset.
std::size_t peak_bytes_since_reset();

}  // namespace nome::bench
