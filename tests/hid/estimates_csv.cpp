#include "estimates_csv.hpp"

#include "lumavel/host/hid_sender.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lumavel::test {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

double number(const std::string& s, const std::string& where) {
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(d)) throw std::runtime_error(where + ": \"" + s + "\" is not a number");
  return d;
}



}  // namespace

std::vector<protocol::Measurement> read_estimates_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open estimates CSV");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file, no header");
  const std::vector<std::string> head = split(line);
  auto col = [&](const char* name, bool required) {
    for (size_t i = 0; i < head.size(); ++i) {
      if (head[i] == name) return static_cast<int>(i);
    }
    if (required) throw std::runtime_error(path + ": line 1: no column \"" + name + "\"");
    return -1;
  };
  const int ct = col("timestamp_ns", true), cv = col("v_xb_mps", true), cd = col("distance_m", true),
            ch = col("heading_rad", true), cs = col("status", true), cf = col("frame_index", false),
            cg = col("gyro_offset_radps", false);
  std::vector<protocol::Measurement> out;
  size_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    const std::string where = path + ": line " + std::to_string(lineno);
    const std::vector<std::string> c = split(line);
    if (c.size() < head.size()) throw std::runtime_error(where + ": " + std::to_string(c.size()) + " columns, header has " + std::to_string(head.size()));
    auto cell = [&](int i) { return c[static_cast<size_t>(i)]; };
    const uint32_t frame = cf >= 0 ? static_cast<uint32_t>(std::strtoul(cell(cf).c_str(), nullptr, 10))
                                   : static_cast<uint32_t>(out.size());
    protocol::Measurement m = host::quantise_measurement(
        std::strtoull(cell(ct).c_str(), nullptr, 10), frame, number(cell(cv), where),
        number(cell(cd), where), number(cell(ch), where),
        static_cast<uint16_t>(number(cell(cs), where)), cg >= 0 ? number(cell(cg), where) : 0.0);
    m.seq = static_cast<uint16_t>(out.size());
    out.push_back(m);
  }
  return out;
}

}  // namespace lumavel::test
