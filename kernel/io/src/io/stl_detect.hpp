#pragma once

#include <string>

namespace nome {

// Whether an STL file's bytes are ASCII: they start with "solid" and do not match the binary size formula
// (a binary file may also start with "solid").
bool stl_looks_ascii(const std::string& bytes);

}  // namespace nome
