#pragma once

namespace nome {

// Writes `value` as printf's "%.17g" does (the digits that round-trip every double) at `at`, which has
// room for 32 bytes, and returns the end. Several times faster than std::to_chars with a precision for
// the coordinates of meshes, whose OBJ export it dominates; the same characters for every value.
char* print_double_g17(char* at, double value);

}  // namespace nome
