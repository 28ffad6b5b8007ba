#include "csv.hpp"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <cstdio>

#include "lumavel/core/status.hpp"
#include "lumavel/units/si.hpp"

namespace lumavel::read {

double v_mps(const protocol::Measurement& m) { return si::Speed::to_si(m.v); }
double distance_m(const protocol::Measurement& m) { return si::Distance::to_si(m.distance); }
double heading_rad(const protocol::Measurement& m) { return si::Angle::to_si(m.heading); }
double gyro_offset_radps(const protocol::Measurement& m) { return si::Rate::to_si(m.gyro_offset); }

std::string csv_header() {
  return "timestamp_ns,v_xb_mps,distance_m,heading_rad,status,gyro_offset_radps,frame_index,seq,overruns";
}

std::string csv_row(const protocol::Measurement& m) {
  // Shortest round-trip decimals, as `lumavel-sim run` writes them: for the
  // fixed engine the two CSVs are then equal character for character.
  char line[256];
  char* const end = line + sizeof line;
  char* p = std::to_chars(line, end, m.t_ns).ptr;
  for (const double x : {v_mps(m), distance_m(m), heading_rad(m)}) {
    *p++ = ',';
    p = std::to_chars(p, end, x, std::chars_format::general).ptr;
  }
  *p++ = ',';
  p = std::to_chars(p, end, m.status).ptr;
  *p++ = ',';
  p = std::to_chars(p, end, gyro_offset_radps(m), std::chars_format::general).ptr;
  for (const uint64_t n : {uint64_t{m.frame_index}, uint64_t{m.seq}, uint64_t{m.overruns}}) {
    *p++ = ',';
    p = std::to_chars(p, end, n).ptr;
  }
  return std::string(line, p);
}

std::string status_names(uint16_t status) {
  if (status == 0) return "ok";
  std::string s;
  for (const StatusFlagInfo& n : kStatusFlags) {
    if (status & n.flag) s += (s.empty() ? "" : "|") + std::string(n.name);
  }
  return s;
}

}  // namespace lumavel::read
