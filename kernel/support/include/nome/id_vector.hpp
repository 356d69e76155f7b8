#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "nome/id.hpp"

namespace nome {

// A contiguous array of T with one entry per element of one kind, read and written by that kind's id
// (Id<Kind>): a parameter's value is found by a ParameterId, never by a placement's.
template <class IdType, class T>
class IdVector {
 public:
  IdVector() = default;
  explicit IdVector(std::vector<T> items) : items_(std::move(items)) {}

  const T& operator[](IdType id) const { return items_[id.index()]; }
  T& operator[](IdType id) { return items_[id.index()]; }

  std::size_t size() const { return items_.size(); }
  bool empty() const { return items_.empty(); }
  bool contains(IdType id) const { return id.is_valid() && id.index() < items_.size(); }
  // Appends an entry; returns its id.
  IdType push_back(T item) {
    items_.push_back(std::move(item));
    return IdType(Index(items_.size() - 1));
  }
  void clear() { items_.clear(); }

  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }
  auto begin() { return items_.begin(); }
  auto end() { return items_.end(); }
  const T& front() const { return items_.front(); }

  bool operator==(const IdVector&) const = default;

 private:
  std::vector<T> items_;
};

}  // namespace nome
