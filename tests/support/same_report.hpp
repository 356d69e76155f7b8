#pragma once

#include "nome/mesh/topology_report.hpp"

namespace nome::test {

// Every count of the two reports and of each part compared (Catch checks): a report derived or counted
// another way must give the same numbers in the same part order.
void check_same_report(const TopologyReport& got, const TopologyReport& want);

}  // namespace nome::test
