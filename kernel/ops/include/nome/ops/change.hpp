#pragma once

namespace nome {

// What a step on the way from a slider to the screen changed in what it hands on: nothing, the positions
// (and face colours) of the same polygons, or the topology. Each step tells the next, so that no step
// compares arrays to find out again.
enum class Change { none, positions, topology };

// Both changes at once: new topology includes new positions.
constexpr Change combined(Change a, Change b) {
  return a == Change::topology || b == Change::topology     ? Change::topology
         : a == Change::positions || b == Change::positions ? Change::positions
                                                            : Change::none;
}

}  // namespace nome
