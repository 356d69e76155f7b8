#include "nome/mesh/attributes.hpp"

#include <algorithm>

#include "nome/error.hpp"

namespace nome {

bool Attributes::operator==(const Attributes& other) const {
  if (entries_.size() != other.entries_.size()) return false;
  for (const Entry& e : entries_) {
    const Entry* o = other.entry(e.name);
    if (!o || o->rule != e.rule || (o->column != e.column && !e.column->equals(*o->column))) return false;
  }
  return true;
}

void Attributes::remove(std::string_view name) {
  std::erase_if(entries_, [&](const Entry& e) { return e.name == name; });
}

void Attributes::add_column(std::string name, AttributeRule rule, std::unique_ptr<AttributeColumn> column) {
  remove(name);
  entries_.push_back({std::move(name), rule, std::move(column)});
}

void Attributes::append(const Attributes& other, std::size_t size) {
  for (const Entry& o : other.entries_) {
    Entry* e = writable_entry(o.name);
    if (!e) {
      // Start from the other's fallback only: no values for the elements already here.
      entries_.push_back({o.name, o.rule, o.column->gathered({})});
      e = &entries_.back();
    }
    if (!e->column->append(*o.column, size)) throw_type_mismatch(*e);
  }
}

Attributes::Entry* Attributes::entry(std::string_view name) {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
  return it == entries_.end() ? nullptr : &*it;
}

Attributes::Entry* Attributes::writable_entry(std::string_view name) {
  Entry* e = entry(name);
  if (e && e->column.use_count() > 1) e->column = std::shared_ptr<AttributeColumn>(e->column->clone());
  return e;
}

const Attributes::Entry* Attributes::entry(std::string_view name) const {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
  return it == entries_.end() ? nullptr : &*it;
}

void Attributes::throw_type_mismatch(const Entry& e) {
  throw InvalidInputError("attribute '" + e.name + "' holds " + e.column->type().name() +
                          " values, not the type asked for");
}

Attributes carried(const Attributes& input, std::span<const Index> parents) {
  Attributes out;
  for (const Attributes::Entry& e : input.entries()) {
    if (e.rule == AttributeRule::drop) continue;
    out.add_column(e.name, e.rule, e.column->gathered(parents));
  }
  return out;
}

Attributes carried(const Attributes& input, const ElementOrigins& origins) {
  if (!origins.is_identity) return carried(input, std::span<const Index>(origins.parents));
  Attributes out = input;
  for (const Attributes::Entry& e : input.entries())
    if (e.rule == AttributeRule::drop) out.remove(e.name);
  return out;
}

}  // namespace nome
