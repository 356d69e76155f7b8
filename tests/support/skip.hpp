#pragma once

#include <catch2/catch.hpp>

#include <string>

namespace nome::test {

// Whether a test that cannot find what it needs fails instead of skipping: under CI (`CI` set) nothing
// may pass silently for want of the shared examples, llvmpipe or node.
bool skips_fail();

// Appends the reason to the file NOME_SKIP_LOG names (ctest sets it; `make test` counts its lines).
void record_skip(const std::string& reason);

}  // namespace nome::test

// Ends the test case for want of something outside the project: a failure under CI, elsewhere a
// warning and a line in the skip log. Checks that need nothing missing belong before it.
#define NOME_SKIP(reason)                                  \
  do {                                                     \
    const std::string nome_skip_reason_ = (reason);        \
    if (nome::test::skips_fail()) FAIL(nome_skip_reason_); \
    nome::test::record_skip(nome_skip_reason_);            \
    WARN("skipped: " << nome_skip_reason_);                \
    return;                                                \
  } while (false)
