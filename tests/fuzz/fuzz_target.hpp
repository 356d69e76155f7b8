#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "nome/error.hpp"

namespace nome::fuzz {

// One fuzz target: the function libFuzzer calls in the fuzz build, and the regression replay calls in the
// test suite (tests/io/fuzz_regression_test.cpp), by the name of its folder in tests/data/fuzz/.
using FuzzTarget = int (*)(const uint8_t* data, size_t size);

// A reader's refusal of untrusted input is fine when it is a user-input error located in the input
// (`FILE:...`); a broken precondition (InvalidInputError) or an unlocated message is a bug: abort, so
// that libFuzzer records the input and the replay fails.
void require_located_refusal(const Error& error, std::string_view file);

}  // namespace nome::fuzz

// Defines fuzz target NAME: `NOME_FUZZ_TARGET(obj) { ...body using data and size... }` makes
// nome::fuzz::obj_target, and in the libFuzzer build (NOME_FUZZ_ENTRY) the entry point that calls it.
#ifdef NOME_FUZZ_ENTRY
#define NOME_FUZZ_ENTRY_POINT(name)                                         \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    return nome::fuzz::name##_target(data, size);                           \
  }
#else
#define NOME_FUZZ_ENTRY_POINT(name)
#endif
#define NOME_FUZZ_TARGET(name)                         \
  namespace nome::fuzz {                               \
  int name##_target(const uint8_t* data, size_t size); \
  }                                                    \
  NOME_FUZZ_ENTRY_POINT(name)                          \
  int nome::fuzz::name##_target(const uint8_t* data, size_t size)
