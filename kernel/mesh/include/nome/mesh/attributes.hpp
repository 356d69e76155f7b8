#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "nome/index.hpp"

namespace nome {

// What an operation does with an attribute for the elements it makes from others (see ElementOrigins):
// `copy` gives each its parent's value, `drop` leaves the attribute out of the operation's output.
enum class AttributeRule : std::uint8_t { copy, drop };

// The kinds of value a file format can write one number of.
enum class ScalarKind : std::uint8_t { none, int32, float32 };

// One attribute's values, one per element, behind a type-free interface so that operations carry it
// without knowing what it holds. An element past the end has the fallback value: a soup adds faces
// without touching its attributes, and a column only grows where a value is set.
class AttributeColumn {
 public:
  virtual ~AttributeColumn() = default;
  virtual std::unique_ptr<AttributeColumn> clone() const = 0;
  // A column for elements whose parents are `parents` (no_index: an element made new, the fallback).
  virtual std::unique_ptr<AttributeColumn> gathered(std::span<const Index> parents) const = 0;
  // Appends `other`'s values after `size` elements of this one (the elements between get the fallback);
  // false when `other` holds another type.
  virtual bool append(const AttributeColumn& other, std::size_t size) = 0;
  virtual bool equals(const AttributeColumn& other) const = 0;
  virtual std::size_t size() const = 0;
  virtual const std::type_info& type() const = 0;
  // Numbers for writers of formats that hold per-element numbers (PLY's properties).
  virtual ScalarKind scalar_kind() const { return ScalarKind::none; }
  virtual double scalar(std::size_t) const { return 0.0; }
};

namespace detail {
template <class T>
constexpr ScalarKind scalar_kind_of() {
  if constexpr (std::is_same_v<T, std::int32_t> || std::is_same_v<T, std::uint8_t>) return ScalarKind::int32;
  if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) return ScalarKind::float32;
  return ScalarKind::none;
}
}  // namespace detail

template <class T>
class Column final : public AttributeColumn {
  static_assert(!std::is_same_v<T, bool>, "std::vector<bool> hands out no references: use std::uint8_t");

 public:
  explicit Column(T fallback) : fallback_(std::move(fallback)) {}

  const T& operator[](std::size_t i) const { return i < values_.size() ? values_[i] : fallback_; }
  void set(std::size_t i, const T& value) {
    if (i >= values_.size()) values_.resize(i + 1, fallback_);
    values_[i] = value;
  }
  const T& fallback() const { return fallback_; }
  // The stored values: as many as the highest element set, not necessarily one per element.
  std::vector<T>& values() { return values_; }
  const std::vector<T>& values() const { return values_; }

  std::unique_ptr<AttributeColumn> clone() const override { return std::make_unique<Column>(*this); }
  std::unique_ptr<AttributeColumn> gathered(std::span<const Index> parents) const override {
    auto out = std::make_unique<Column>(fallback_);
    if (values_.empty()) return out;
    out->values_.reserve(parents.size());
    for (Index p : parents) out->values_.push_back(p == no_index ? fallback_ : (*this)[p]);
    return out;
  }
  bool append(const AttributeColumn& other, std::size_t size) override {
    const auto* typed = dynamic_cast<const Column*>(&other);
    if (!typed) return false;
    if (typed->values_.empty()) return true;
    values_.resize(size, fallback_);
    values_.insert(values_.end(), typed->values_.begin(), typed->values_.end());
    return true;
  }
  bool equals(const AttributeColumn& other) const override {
    const auto* typed = dynamic_cast<const Column*>(&other);
    return typed && typed->values_ == values_ && typed->fallback_ == fallback_;
  }
  std::size_t size() const override { return values_.size(); }
  const std::type_info& type() const override { return typeid(T); }
  ScalarKind scalar_kind() const override { return detail::scalar_kind_of<T>(); }
  double scalar(std::size_t i) const override {
    if constexpr (detail::scalar_kind_of<T>() != ScalarKind::none)
      return double((*this)[i]);
    else
      return 0.0;
  }

 private:
  std::vector<T> values_;
  T fallback_;
};

// The named attributes of one kind of element (a soup's or a mesh's faces): each a column of one type
// with its rule. Operations that make new elements carry them all by their rules (carried()) and never
// name one; who sets an attribute reads it back by name and type. Copies share their columns until one of
// them writes (the viewer copies the shown mesh on every slider tick; its attributes stay as they were).
class Attributes {
 public:
  struct Entry {
    std::string name;
    AttributeRule rule = AttributeRule::copy;
    std::shared_ptr<AttributeColumn> column;
  };

  bool operator==(const Attributes& other) const;

  // The attribute `name` of type T, added with `fallback` and `rule` when there is none; throws
  // InvalidInputError when it is there with another type.
  template <class T>
  Column<T>& add(std::string_view name, T fallback, AttributeRule rule = AttributeRule::copy) {
    if (Entry* e = writable_entry(name)) return typed<T>(*e);
    entries_.push_back({std::string(name), rule, std::make_shared<Column<T>>(std::move(fallback))});
    return static_cast<Column<T>&>(*entries_.back().column);
  }
  // The attribute `name` when it is there with type T.
  template <class T>
  const Column<T>* find(std::string_view name) const {
    const Entry* e = entry(name);
    return e ? dynamic_cast<const Column<T>*>(e->column.get()) : nullptr;
  }
  // For writing: a column shared with a copy is copied first.
  template <class T>
  Column<T>* find(std::string_view name) {
    Entry* e = entry(name);
    if (!e || !dynamic_cast<Column<T>*>(e->column.get())) return nullptr;
    return dynamic_cast<Column<T>*>(writable_entry(name)->column.get());
  }
  // Adds a column made elsewhere (a reader's, an operation's); replaces one of the same name.
  void add_column(std::string name, AttributeRule rule, std::unique_ptr<AttributeColumn> column);
  void remove(std::string_view name);
  bool empty() const { return entries_.empty(); }
  const std::vector<Entry>& entries() const { return entries_; }

  // Appends `other`'s values after `size` elements of these: an attribute only one side has takes the
  // fallback on the other side's elements. Throws InvalidInputError when one name has two types.
  void append(const Attributes& other, std::size_t size);

 private:
  Entry* entry(std::string_view name);
  const Entry* entry(std::string_view name) const;
  // The entry with a column of its own (not shared with a copy).
  Entry* writable_entry(std::string_view name);
  template <class T>
  static Column<T>& typed(Entry& e) {
    auto* column = dynamic_cast<Column<T>*>(e.column.get());
    if (!column) throw_type_mismatch(e);
    return *column;
  }
  [[noreturn]] static void throw_type_mismatch(const Entry& e);

  std::vector<Entry> entries_;
};

// Where each element an operation made came from: parents[i] is the input element that output element i
// is a copy of, a child of, or the rim of (no_index: made new). Operations that keep every element in its
// place (a merge's faces) give the identity: empty parents with `is_identity`.
struct ElementOrigins {
  std::vector<Index> parents;
  bool is_identity = false;

  static ElementOrigins identity() { return {{}, true}; }
};

// The attributes of an operation's output, carried from its input's by each attribute's rule.
Attributes carried(const Attributes& input, const ElementOrigins& origins);
Attributes carried(const Attributes& input, std::span<const Index> parents);

}  // namespace nome
