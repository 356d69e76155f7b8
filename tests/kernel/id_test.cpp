#include <catch2/catch.hpp>

#include <type_traits>
#include <unordered_set>

#include "nome/id_vector.hpp"
#include "nome/scene/ids.hpp"

using namespace nome;
using scene::InstanceId;
using scene::ParameterId;
using scene::PlacementId;

// Ids of different kinds never convert into each other or into integers: mixing them does not compile.
static_assert(!std::is_convertible_v<ParameterId, PlacementId>);
static_assert(!std::is_convertible_v<PlacementId, InstanceId>);
static_assert(!std::is_convertible_v<ParameterId, Index>);
static_assert(!std::is_convertible_v<Index, ParameterId>);
template <class Array, class Key>
concept is_read_by = requires(Array array, Key key) {
  array[key];
};
static_assert(is_read_by<IdVector<ParameterId, double>, ParameterId>);
static_assert(!is_read_by<IdVector<ParameterId, double>, PlacementId>);
static_assert(!is_read_by<IdVector<ParameterId, double>, Index>);
static_assert(sizeof(ParameterId) == 4);

TEST_CASE("an id names one element of its kind or none, and orders and hashes as its index", "[kernel]") {
  CHECK_FALSE(ParameterId().is_valid());
  CHECK(ParameterId(3).is_valid());
  CHECK(ParameterId(3).index() == 3);
  CHECK(ParameterId(2) < ParameterId(3));
  CHECK(ParameterId(3) == ParameterId(3));
  const std::unordered_set<ParameterId> set{ParameterId(1), ParameterId(1), ParameterId(4)};
  CHECK(set.size() == 2);
}

TEST_CASE("an id vector gives each entry appended the next id and is read by those ids", "[kernel]") {
  IdVector<ParameterId, double> values;
  const ParameterId a = values.push_back(0.5);
  const ParameterId b = values.push_back(2.0);
  CHECK(a == ParameterId(0));
  CHECK(b == ParameterId(1));
  CHECK(values[b] == 2.0);
  values[a] = 1.5;
  CHECK(values[a] == 1.5);
  CHECK(values.contains(b));
  CHECK_FALSE(values.contains(ParameterId(2)));
  CHECK_FALSE(values.contains(ParameterId()));
  CHECK(values.size() == 2);
  values.clear();
  CHECK(values.empty());
}
