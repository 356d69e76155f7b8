#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace nome {

// The names of a soup's or mesh's vertices or faces: one list shared by copies until one of them changes
// it. A scene's placement, its instance, the combined soup and the pipeline's mesh hold the same names (a
// sweep has hundreds of thousands); copying them each time cost more than building the mesh.
// Reading is a vector's; a change through a copy that shares the list copies it first (iterators and
// references into a shared list stay valid, those into this copy's list do not).
class Names {
 public:
  using value_type = std::string;
  using const_iterator = std::vector<std::string>::const_iterator;

  Names() = default;
  Names(std::vector<std::string> list)  // NOLINT(google-explicit-constructor): a list of names is one
      : list_(list.empty() ? nullptr : std::make_shared<std::vector<std::string>>(std::move(list))) {}
  Names(std::initializer_list<std::string> list) : Names(std::vector<std::string>(list)) {}
  Names(const Names&) = default;
  Names(Names&& other) noexcept : list_(std::move(other.list_)) {}
  Names& operator=(const Names&) = default;
  Names& operator=(Names&& other) noexcept {
    list_ = std::move(other.list_);
    return *this;
  }
  ~Names() = default;

  std::size_t size() const { return list_ ? list_->size() : 0; }
  bool empty() const { return size() == 0; }
  const std::string& operator[](std::size_t i) const { return (*list_)[i]; }
  const std::string& front() const { return list_->front(); }
  const std::string& back() const { return list_->back(); }
  const_iterator begin() const { return list().begin(); }
  const_iterator end() const { return list().end(); }
  const std::vector<std::string>& list() const;
  operator const std::vector<std::string>&() const { return list(); }  // NOLINT: read as the vector it is

  // Changes: the list is this copy's own afterwards. Reading never copies, so there is no non-const
  // operator[] or begin(): a change says so with writable().
  std::vector<std::string>& writable();
  void push_back(std::string name) { writable().push_back(std::move(name)); }
  template <class... Args>
  std::string& emplace_back(Args&&... args) {
    return writable().emplace_back(std::forward<Args>(args)...);
  }
  void reserve(std::size_t n) { writable().reserve(n); }
  void resize(std::size_t n) {
    if (n != size()) writable().resize(n);
  }
  void resize(std::size_t n, const std::string& name) {
    if (n != size()) writable().resize(n, name);
  }
  // Appends [first, last), which must not point into this list.
  template <class It>
  void append(It first, It last) {
    std::vector<std::string>& own = writable();
    own.insert(own.end(), first, last);
  }
  void clear() { list_.reset(); }
  void pop_back() { writable().pop_back(); }

  // The same names (lists shared by copies compare at once).
  bool operator==(const Names& other) const { return list_ == other.list_ || list() == other.list(); }

 private:
  std::shared_ptr<std::vector<std::string>> list_;  // null: no names
};

}  // namespace nome
