// The CSV that `lumavel-read stream` and `replay` write. The first six
// columns are those of the estimates CSV of `lumavel-sim run`, same names and
// same formatting (shortest round-trip decimal of the exact fixed-point value),
// so for the fixed engine the two are equal line by line.
#pragma once
#include <cstdint>
#include <string>

#include "lumavel/protocol/reports.hpp"

namespace lumavel::read {

std::string csv_header();  // no newline
std::string csv_row(const protocol::Measurement& m);  // no newline
std::string status_names(uint16_t status);  // "CONVERGING|LOW_TEXTURE", "ok" for 0

double v_mps(const protocol::Measurement& m);
double distance_m(const protocol::Measurement& m);
double heading_rad(const protocol::Measurement& m);
double gyro_offset_radps(const protocol::Measurement& m);

}  // namespace lumavel::read
