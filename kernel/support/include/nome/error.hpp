#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace nome {

// The small typed set (pmp-library's model). User-content errors carry a location in their message,
// already formatted as `file:line:col: what`; programmer errors start with the function name.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A caller broke a precondition or passed an argument outside its domain.
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

// The polygons do not form a 2-manifold (the message names the elements). build_mesh also lists each
// problem with the face it is about, so that a caller knowing where faces come from can locate them.
class TopologyError : public Error {
 public:
  struct Problem {
    std::string text;
    std::uint32_t face = std::uint32_t(-1);  // none: a problem of a vertex alone
  };
  using Error::Error;
  TopologyError(const std::string& what, std::vector<Problem> problems)
      : Error(what), problems_(std::move(problems)) {}
  const std::vector<Problem>& problems() const { return problems_; }

 private:
  std::vector<Problem> problems_;
};

// Reading or writing a file failed, or a file's content is malformed.
class IoError : public Error {
 public:
  using Error::Error;
};

// A request whose output would exceed the memory budget (the message gives the estimate).
class BudgetError : public Error {
 public:
  using Error::Error;
};

}  // namespace nome
