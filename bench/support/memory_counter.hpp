#pragma once

#include <cstddef>

// Resident bytes and their peak, from /proc/self/status: the kernel's big arrays are pages mapped for
// them (nome/buffer.hpp), which no operator new sees.
namespace nome::bench {

// Starts a new peak measurement from the bytes resident now.
void reset_peak();
// The highest resident byte count since reset_peak(), minus the bytes resident at that reset.
std::size_t peak_bytes_since_reset();

}  // namespace nome::bench
