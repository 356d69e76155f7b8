#pragma once

#include <cstdio>
#include <cstdlib>

// An internal invariant of the kernel: not something a user or caller can cause, so it is checked only
// where NOME_ASSERTIONS is defined (debug, test and fuzz builds), where a broken one stops the program
// with its place; elsewhere the compiler may assume it.
#if defined(NOME_ASSERTIONS)
#define NOME_ASSERT(condition)                                                                            \
  ((condition)                                                                                            \
       ? void(0)                                                                                          \
       : (std::fprintf(stderr, "%s:%d: internal invariant broken: %s\n", __FILE__, __LINE__, #condition), \
          std::abort()))
#else
#define NOME_ASSERT(condition) ((condition) ? void(0) : __builtin_unreachable())
#endif
