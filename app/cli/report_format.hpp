#pragma once

#include <string>

#include "nome/mesh/topology_report.hpp"

namespace nome::cli {

// The report as one JSON object (its keys are the command line's contract: scripts read them).
std::string report_json(const TopologyReport& report);
// The report as aligned text for people.
std::string report_text(const TopologyReport& report);

}  // namespace nome::cli
