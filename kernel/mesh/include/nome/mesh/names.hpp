#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace nome {

// The names of a soup's or mesh's vertices or faces: one list shared by copies until one of them changes
// it. A scene's placement, its instance, the combined soup and the pipeline's mesh hold the same names (a
// sweep has hundreds of thousands); copying them each time cost more than building the mesh.
//
// A generator whose names follow a grid (a sweep's `v{i}_{j}`) gives the rule instead of the strings:
// a name is made when it is read, and the whole list only when something walks it (begin(), list()).
// Prefixing an instance's names and appending pieces keep rules as rules, so evaluating a sweep into the
// pipeline makes none of its names.
//
// Reading by index returns the name by value. A change through a copy that shares the list copies it
// first; there is no non-const operator[] or begin(): a change says so with writable().
class Names {
 public:
  using value_type = std::string;
  using const_iterator = std::vector<std::string>::const_iterator;

  // The names prefix + letter + i + '_' + j + suffix, row by row: i from first_row, j in [0, columns),
  // one name per suffix for each (i, j), the suffixes in order.
  struct Grid {
    char letter = 'v';
    std::size_t first_row = 0;
    std::size_t columns = 1;
    std::vector<std::string> suffixes{""};
    bool operator==(const Grid&) const = default;
  };

  Names() = default;
  Names(std::vector<std::string> list);  // NOLINT(google-explicit-constructor): a list of names is one
  Names(std::initializer_list<std::string> list) : Names(std::vector<std::string>(list)) {}
  // `count` names of the grid (a whole number of rows is not required).
  static Names grid(const Grid& grid, std::size_t count);

  std::size_t size() const;
  bool empty() const { return size() == 0; }
  std::string operator[](std::size_t i) const;
  std::string front() const { return (*this)[0]; }
  std::string back() const { return (*this)[size() - 1]; }
  const_iterator begin() const { return list().begin(); }
  const_iterator end() const { return list().end(); }
  // Every name as a string (made once and kept while the names do not change).
  const std::vector<std::string>& list() const;
  operator const std::vector<std::string>&() const { return list(); }  // NOLINT: read as the vector it is

  // Changes: the list is this copy's own afterwards.
  std::vector<std::string>& writable();
  void push_back(std::string name) { writable().push_back(std::move(name)); }
  template <class... Args>
  std::string& emplace_back(Args&&... args) {
    return writable().emplace_back(std::forward<Args>(args)...);
  }
  void reserve(std::size_t n) { writable().reserve(n); }
  // Growing adds empty names; grid names stay rules.
  void resize(std::size_t n);
  // Appends the other names (rules stay rules).
  void append(const Names& other);
  // Every name with `prefix` in front (rules stay rules).
  void add_prefix(const std::string& prefix);
  void clear() { state_.reset(); }
  void pop_back() { writable().pop_back(); }

  // The same names (copies that share their list compare at once, rules by their parameters).
  bool operator==(const Names& other) const;
  // Whether the two hold one list or rule (a copy that nothing changed since).
  bool shares_with(const Names& other) const { return state_ == other.state_; }
  // How many times a rule's names have been made into a whole list in this process (tests hold the
  // interactive paths to none).
  static std::uint64_t lists_made();

 private:
  struct State;
  explicit Names(std::shared_ptr<State> state) : state_(std::move(state)) {}
  std::shared_ptr<State> state_;  // null: no names
};

}  // namespace nome
