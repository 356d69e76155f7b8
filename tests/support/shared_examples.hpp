#pragma once

#include "support/skip.hpp"

#include <string>

namespace nome::test {

// The example files written by others (the `shared` folder's examples/<folder>/ beside the checkout; CI
// has it): they are read from there, never copied into the project. NOME_SHARED_DIR names another shared
// folder: `make test` re-runs the cases that read it with an empty one, as a clone without it would.
// Each case that asks is written to the file NOME_SHARED_USE_LOG names (its program and its name), which
// is how that re-run knows them.
std::string shared_examples_dir(const std::string& folder);
bool has_shared_examples(const std::string& folder);

}  // namespace nome::test

// Ends the test case when the shared examples folder is absent (NOME_SKIP: a failure under CI).
#define NOME_NEEDS_SHARED_EXAMPLES(folder)      \
  if (!nome::test::has_shared_examples(folder)) \
  NOME_SKIP(nome::test::shared_examples_dir(folder) + " is absent (../shared)")
