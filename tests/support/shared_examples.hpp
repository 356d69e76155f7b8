#pragma once

#include "support/skip.hpp"

#include <string>

namespace nome::test {

// The example files written by others (the `shared` folder's examples/<folder>/ beside the checkout; CI
// has it):
// they are read from there, never copied into the project.
std::string shared_examples_dir(const std::string& folder);
bool has_shared_examples(const std::string& folder);

}  // namespace nome::test

// Ends the test case when the shared examples folder is absent (NOME_SKIP: a failure under CI).
#define NOME_NEEDS_SHARED_EXAMPLES(folder)      \
  if (!nome::test::has_shared_examples(folder)) \
  NOME_SKIP(nome::test::shared_examples_dir(folder) + " is absent (../shared)")
