// Reads an estimates CSV (`lumavel-sim run` output, or lumavel-read's own CSV)
// into measurements quantised to the report's fixed-point formats. Columns are
// found by name: timestamp_ns, v_xb_mps, distance_m, heading_rad, status
// (frame_index optional). Throws std::runtime_error naming file and line.
#pragma once
#include <string>
#include <vector>

#include "lumavel/protocol/reports.hpp"

namespace lumavel::test {

std::vector<protocol::Measurement> read_estimates_csv(const std::string& path);

}  // namespace lumavel::test
