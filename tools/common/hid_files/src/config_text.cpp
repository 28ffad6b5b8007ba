#include "lumavel/host/config_text.hpp"

#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/line_ends.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/units/si.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <limits>
#include <utility>
#include <stdexcept>

namespace lumavel::host {

namespace proto = lumavel::protocol;

namespace {

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

// A value that cannot be stored in its field. apply_setting adds the key,
// the value and the key's rule: a value that is a number beyond what the
// field holds (-3 columns, 1e300 px) is told by the rule alone.
class BadValue : public std::runtime_error {
 public:
  BadValue(const std::string& problem, bool beyond) : std::runtime_error(problem), beyond_field(beyond) {}
  bool beyond_field;  // a number, but too large or too small for the field
};

// Read as the recording tables read their numbers (decimal_text.hpp).
double parse_double(const std::string& v) {
  const DecimalText d = read_decimal(v);
  using P = DecimalText::Problem;
  if (d.problem == P::kHexadecimal)
    throw BadValue("a hexadecimal number: only decimal numbers are read", false);
  if (d.problem == P::kNotFinite && std::isnan(d.value)) throw BadValue("not a finite number", false);
  // Too small for a double: not beyond the field but unreadable (was: 'lens_cam0
  // value 2: 1e-400 rad is outside [-1, 1)', 'misalignment_rad = 1e-400:
  // misalignment must be -0.35..0.35 rad', rules the value meets).
  if (d.underflow) throw BadValue(kNearerZeroThanAnyNumber, false);
  if (d.problem == P::kOverflow || d.problem == P::kNotFinite) throw BadValue("beyond any field", true);
  if (d.problem != P::kNone) throw BadValue("not a number", false);
  return d.value;
}

// Read as the command lines read their whole numbers (decimal_text.hpp): "040" is refused.
long long parse_int(const std::string& v, long long lo, long long hi) {
  const WholeText w = read_whole(v);
  using P = WholeText::Problem;
  if (w.problem == P::kNotAWholeNumber || w.problem == P::kLeadingZero) throw BadValue(whole_text_rule(w.problem), false);
  if (w.problem == P::kOverflow || w.value < lo || w.value > hi) throw BadValue("beyond its field", true);
  return w.value;
}

// Physical value to a signed 32-bit fixed-point number with `frac` bits.
int32_t to_q(const std::string& v, int frac) {
  const double q = std::round(std::ldexp(parse_double(v), frac));
  if (q < -2147483648.0 || q > 2147483647.0) throw BadValue("beyond its fixed-point field", true);
  return static_cast<int32_t>(q);
}

// The shortest decimal that reads back to the same fixed-point value, so that
// `config get` prints 0.07, not 0.0700000003, and get -> set is lossless.
std::string num_q(int32_t q, int frac) {
  const double v = si::from_q(q, frac);
  for (int digits = 1; digits < 17; ++digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::llround(std::ldexp(std::strtod(b, nullptr), frac)) == q) return b;
  }
  return num(v);
}

std::string format_kernels(const proto::DeviceConfig& c) {
  std::string s;
  for (int i = 0; i < c.kernel_count && i < proto::kWireKernels; ++i) {
    s += (i ? "," : "") + std::to_string(c.kernels[i].order) + ":" + num_q(c.kernels[i].sigma, fx::kAngleFrac);
  }
  return s;
}

void parse_kernels(proto::DeviceConfig& c, const std::string& v) {
  proto::DeviceConfig n = c;
  for (auto& k : n.kernels) k = proto::KernelSetting{0, 0};
  n.kernel_count = 0;
  size_t start = 0;
  while (start <= v.size()) {
    const size_t comma = v.find(',', start);
    const std::string item = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const size_t colon = item.find(':');
    if (colon == std::string::npos || n.kernel_count >= proto::kWireKernels) {
      throw std::runtime_error("kernels: \"" + shown_path(v) + "\" is not ORDER:SIGMA_RAD[,...] with at most " +
                               std::to_string(proto::kWireKernels) + " kernels");
    }
    proto::KernelSetting& k = n.kernels[n.kernel_count++];
    // Blanks before an order are dropped, as they were ("1:0.07, 1:0.14").
    const size_t order_at = std::min(item.find_first_not_of(" \t"), colon);
    k.order = static_cast<uint8_t>(parse_int(item.substr(order_at, colon - order_at), 0, 255));
    k.sigma = to_q(item.substr(colon + 1), fx::kAngleFrac);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  c = n;
}

std::string format_lens(const std::vector<EdgeOffsetQ15>& t) {
  if (t.empty()) return "none";
  std::string s;
  for (size_t i = 0; i < t.size(); ++i) s += (i ? "," : "") + num_q(t[i], fx::kEdgeOffsetFrac);
  return s;
}

// Comma-separated corrections in rad, each to Q15 ("none" or empty: no table).
std::vector<EdgeOffsetQ15> parse_lens(const std::string& key, const std::string& v) {
  std::vector<EdgeOffsetQ15> out;
  if (v.empty() || v == "none") return out;
  size_t start = 0;
  for (;;) {
    const size_t comma = v.find(',', start);
    const std::string item = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string where = key + " value " + std::to_string(out.size() + 1);
    int32_t q = 0;
    try {
      q = to_q(item, fx::kEdgeOffsetFrac);
    } catch (const BadValue& e) {
      if (!e.beyond_field) throw std::runtime_error(where + ": \"" + shown_path(item) + "\" is " + e.what());
      q = INT32_MAX;
    }
    // A value just below 1 rad rounds to 32768/32768 = 1 (was: "0.999985 rad
    // is outside [-1, 1)", a refusal its own words allow): said as such.
    if (q == 32768)
      throw std::runtime_error(where + ": " + shown_path(item) +
                               " rad rounds to 1 rad in the table's steps of 1/32768 rad, outside [-1, 1): at most "
                               "0.99997 rad (32767/32768)");
    if (q < -32768 || q > 32767) throw std::runtime_error(where + ": " + shown_path(item) + " rad is outside [-1, 1)");
    out.push_back(static_cast<EdgeOffsetQ15>(q));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool flag(const std::string& v) { return parse_int(v, 0, 1) != 0; }

// The rule a key's value must follow, in words (proto::rule_of where the key
// sets a field the device validates).
std::string rule_of_key(const std::string& key);

}  // namespace

const char* config_keys_help() {
  return "  width, height            working resolution (columns, rows)\n"
         "  baseline_m               h: x of cam1's optical centre minus cam0's, m (signed)\n"
         "  misalignment_rad         yaw from cam0 to cam1, rad\n"
         "  fu0_px cu0_px fu1_px cu1_px  intrinsics at the working resolution, px\n"
         "  look                     left | right (side the cameras look to)\n"
         "  cam0_upside_down, cam1_upside_down   0 | 1\n"
         "  normaliser_sigma_rad     order-0 window, rad\n"
         "  kernels                  ORDER:SIGMA_RAD[,ORDER:SIGMA_RAD...], e.g. 1:0.07,1:0.14\n"
         "  tau_us                   observer time constant (gain 1/tau), us\n"
         "  frame_period_us, max_gap_us, gyro_gap_us   timing, us\n"
         "  low_texture              rms of F1-F0 below which V is held\n"
         "  saturated_permille       clipped pixels that raise SATURATED, per mille\n"
         "  baseline_correction, gyro_offset_learning, photometric_balance, elevation_band,\n"
         "  photometric_match\n"
         "                           estimator options, 0 | 1\n"
         "  still_distance_m         image change below which the rig counts as still, m\n"
         "  still_min_us             stillness before the gyro offset is taken, us\n"
         "  lens_cam0, lens_cam1     lens correction of each column edge (width + 1 values,\n"
         "                           rad, comma-separated, added to the pinhole edges) or none\n";
}

std::string format_setup(const DeviceSetup& d) {
  const proto::DeviceConfig& c = d.config;
  std::string s;
  auto line = [&s](const char* k, const std::string& v) { s += std::string(k) + "=" + v + "\n"; };
  line("width", std::to_string(c.width));
  line("height", std::to_string(c.height));
  line("baseline_m", num_q(c.baseline, fx::kLengthFrac));
  line("misalignment_rad", num_q(c.misalignment, fx::kAngleFrac));
  line("fu0_px", num_q(c.fu[0], fx::kPixelFrac));
  line("cu0_px", num_q(c.cu[0], fx::kPixelFrac));
  line("fu1_px", num_q(c.fu[1], fx::kPixelFrac));
  line("cu1_px", num_q(c.cu[1], fx::kPixelFrac));
  line("look", (c.orientation & proto::kLooksRight) ? "right" : "left");
  line("cam0_upside_down", (c.orientation & proto::kCam0UpsideDown) ? "1" : "0");
  line("cam1_upside_down", (c.orientation & proto::kCam1UpsideDown) ? "1" : "0");
  line("normaliser_sigma_rad", num_q(c.normaliser_sigma, fx::kAngleFrac));
  line("kernels", format_kernels(c));
  line("tau_us", std::to_string(c.tau_us));
  line("frame_period_us", std::to_string(c.frame_period_us));
  line("max_gap_us", std::to_string(c.max_gap_us));
  line("gyro_gap_us", std::to_string(c.gyro_gap_us));
  line("low_texture", num_q(c.low_texture, fx::kValueFrac));
  line("saturated_permille", std::to_string(c.saturated_permille));
  line("baseline_correction", (c.options & kOptionBaselineCorrection) ? "1" : "0");
  line("gyro_offset_learning", (c.options & kOptionGyroOffsetLearning) ? "1" : "0");
  line("photometric_balance", (c.options & kOptionPhotometricBalance) ? "1" : "0");
  line("elevation_band", (c.options & kOptionElevationBand) ? "1" : "0");
  line("photometric_match", (c.options & kOptionPhotometricMatch) ? "1" : "0");
  line("still_distance_m", num_q(c.still_distance, fx::kLengthFrac));
  line("still_min_us", std::to_string(c.still_min_us));
  line("lens_cam0", format_lens(d.lens[0]));
  line("lens_cam1", format_lens(d.lens[1]));
  return s;
}

namespace {

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// KEY and VALUE of "KEY=VALUE", spaces around them dropped.
std::pair<std::string, std::string> split_setting(const std::string& kv) {
  const size_t eq = kv.find('=');
  const std::string k = eq == std::string::npos ? std::string() : trimmed(kv.substr(0, eq));
  if (k.empty())
    throw std::runtime_error("\"" + shown_path(kv) + "\" is not KEY=VALUE (keys: `lumavel-read config --help`)");
  return {k, trimmed(kv.substr(eq + 1))};
}

// The text of FILE; refuses what is not a readable regular file by its name.
std::string read_settings_file(const std::string& path) {
  if (const std::string why = why_not_a_file(path, "configuration file"); !why.empty()) {
    // --file takes several names: in `--file rig.cfg width=40` the setting is one.
    const bool setting = why == "does not exist" && path.find('=') != std::string::npos;
    throw std::runtime_error(shown_path(path) + ": " + why +
                             (setting ? " (a KEY=VALUE after --file is read as another file name: give the settings "
                                        "before --file, or after --)"
                                      : ""));
  }
  if (const std::string why = why_too_big_for_text(path, "a configuration file holds a few KEY=VALUE lines");
      !why.empty())
    throw std::runtime_error(shown_path(path) + ": " + why);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(shown_path(path) + ": cannot open configuration file: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Calls f(line_number, line) for every setting line (no comment, no blank)
// of the file `name`. Lines end as a recording table's do: LF or CR LF; a CR
// with more after it (CR-only line ends) is refused at its line, saying so.
// The name goes into messages through shown_path, as every name does (was: a
// file named 'rig<ESC>[2J.cfg' cleared the terminal with its refusals).
template <typename F>
void for_each_setting_line(const std::string& text, const std::string& name, F f) {
  std::istringstream in(text);
  std::string line;
  for (size_t n = 1; std::getline(in, line); ++n) {
    if (n == 1)
      if (const std::string why = why_wide_text(line); !why.empty())
        throw std::runtime_error(shown_path(name) + ":1: " + why);
    if (n == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark
    if (const std::string why = why_cr_inside_line(line); !why.empty())
      throw std::runtime_error(shown_path(name) + ":" + std::to_string(n) + ": " + why);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    f(n, line.substr(start));
  }
}

}  // namespace

namespace {

void apply_value(DeviceSetup& d, const std::string& k, const std::string& v) {
  proto::DeviceConfig& c = d.config;
  const long long u32 = 4294967295LL;
  auto option = [&](uint8_t b) {
    c.options = static_cast<uint8_t>(flag(v) ? (c.options | b) : (c.options & ~b));
  };
  auto bit = [&](uint8_t b) {
    const bool on = flag(v);
    c.orientation = static_cast<uint8_t>(on ? (c.orientation | b) : (c.orientation & ~b));
  };
  if (k == "width") c.width = static_cast<uint16_t>(parse_int(v, 0, 65535));
  else if (k == "height") c.height = static_cast<uint16_t>(parse_int(v, 0, 65535));
  else if (k == "baseline_m") c.baseline = to_q(v, fx::kLengthFrac);
  else if (k == "misalignment_rad") c.misalignment = to_q(v, fx::kAngleFrac);
  else if (k == "fu0_px") c.fu[0] = to_q(v, fx::kPixelFrac);
  else if (k == "cu0_px") c.cu[0] = to_q(v, fx::kPixelFrac);
  else if (k == "fu1_px") c.fu[1] = to_q(v, fx::kPixelFrac);
  else if (k == "cu1_px") c.cu[1] = to_q(v, fx::kPixelFrac);
  else if (k == "look") {
    if (v != "left" && v != "right")
      throw std::runtime_error("look: use left or right, not \"" + shown_path(v) + "\"");
    c.orientation = static_cast<uint8_t>(v == "right" ? (c.orientation | proto::kLooksRight)
                                                      : (c.orientation & ~proto::kLooksRight));
  } else if (k == "cam0_upside_down") bit(proto::kCam0UpsideDown);
  else if (k == "cam1_upside_down") bit(proto::kCam1UpsideDown);
  else if (k == "normaliser_sigma_rad") c.normaliser_sigma = to_q(v, fx::kAngleFrac);
  else if (k == "kernels") parse_kernels(c, v);
  else if (k == "tau_us") c.tau_us = static_cast<uint32_t>(parse_int(v, 0, u32));
  else if (k == "frame_period_us") c.frame_period_us = static_cast<uint32_t>(parse_int(v, 0, u32));
  else if (k == "max_gap_us") c.max_gap_us = static_cast<uint32_t>(parse_int(v, 0, u32));
  else if (k == "gyro_gap_us") c.gyro_gap_us = static_cast<uint32_t>(parse_int(v, 0, u32));
  else if (k == "low_texture") c.low_texture = to_q(v, fx::kValueFrac);
  else if (k == "saturated_permille") c.saturated_permille = static_cast<uint16_t>(parse_int(v, 0, 65535));
  else if (k == "baseline_correction") option(kOptionBaselineCorrection);
  else if (k == "gyro_offset_learning") option(kOptionGyroOffsetLearning);
  else if (k == "photometric_balance") option(kOptionPhotometricBalance);
  else if (k == "elevation_band") option(kOptionElevationBand);
  else if (k == "photometric_match") option(kOptionPhotometricMatch);
  else if (k == "still_distance_m") c.still_distance = to_q(v, fx::kLengthFrac);
  else if (k == "still_min_us") c.still_min_us = static_cast<uint32_t>(parse_int(v, 0, u32));
  else if (k == "lens_cam0") d.lens[0] = parse_lens(k, v);
  else if (k == "lens_cam1") d.lens[1] = parse_lens(k, v);
  else throw std::runtime_error("unknown configuration key \"" + shown_path(k) + "\"; keys:\n" + config_keys_help());
}

}  // namespace

void apply_setting(DeviceSetup& d, const std::string& kv) {
  // strto* stop at a NUL byte ("9<NUL>0.0092" would be read as 9): refused
  // wherever it is, in a key or a word too.
  const size_t nul = kv.find('\0');
  if (nul != std::string::npos)
    throw std::runtime_error("\"" + shown_path(kv.substr(0, nul)) + "\" is followed by a NUL byte (character " +
                             std::to_string(nul + 1) + "): not a KEY=VALUE setting");
  const auto [k, v] = split_setting(kv);
  try {
    apply_value(d, k, v);
  } catch (const BadValue& e) {
    // "width = 40x: not a whole number; width must be 16..160 columns";
    // "width = -3: width must be 16..160 columns" (as for 0, which parses).
    std::string value = v;
    if (value.size() > 40) value = value.substr(0, 37) + "...";
    value = shown_path(value);  // a control character as \xNN
    const std::string rule = rule_of_key(k);
    throw std::runtime_error(k + " = " + value + ": " +
                             (e.beyond_field ? rule : std::string(e.what()) + (rule.empty() ? "" : "; " + rule)));
  }
}

void apply_settings_text(DeviceSetup& s, const std::string& text, const std::string& name) {
  for_each_setting_line(text, name, [&](size_t n, const std::string& line) {
    try {
      apply_setting(s, line);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(shown_path(name) + ":" + std::to_string(n) + ": " + e.what());
    }
  });
}

void apply_settings_file(DeviceSetup& s, const std::string& path) {
  apply_settings_text(s, read_settings_file(path), path);
}

void GivenSettings::add(const std::string& kv, const std::string& where) {
  try {
    const auto [k, v] = split_setting(kv);
    DeviceSetup scratch;
    scratch.config = proto::default_device_config();
    apply_setting(scratch, kv);  // the value's own form
    items.push_back({where, k, v});
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(where + ": " + e.what());
  }
}

// Within one source (a file, the command line) a key is given once: which of
// two values was meant is not for lumavel to guess (files and the command
// line after them do override earlier ones, as documented). The setting of
// items[first..] with the last one's key, or nullptr.
const GivenSetting* GivenSettings::given_before(size_t first) const {
  for (size_t i = first; i + 1 < items.size(); ++i)
    if (items[i].key == items.back().key) return &items[i];
  return nullptr;
}

void GivenSettings::add_file(const std::string& path) {
  const std::string text = read_settings_file(path);
  const size_t first = items.size();
  for_each_setting_line(text, path, [&](size_t n, const std::string& line) {
    const std::string where = shown_path(path) + ":" + std::to_string(n);
    add(line, where);
    if (const GivenSetting* earlier = given_before(first))
      throw std::runtime_error(where + ": " + items.back().key + " is given again (first at " + earlier->where +
                               "): one value per key in a file");
  });
  if (items.size() == first)
    throw std::runtime_error(shown_path(path) + ": no KEY=VALUE line (only blank lines and # comments)");
}

void GivenSettings::add_command_line(const std::vector<std::string>& settings) {
  const size_t first = items.size();
  for (const std::string& kv : settings) {
    add(kv, "command line");
    if (const GivenSetting* earlier = given_before(first))
      throw std::runtime_error("command line: " + shown_path(kv) + ": " + items.back().key + " is given again (first as " +
                               earlier->key + "=" + shown_path(earlier->value) + "): one value per key on the command line");
  }
}

bool GivenSettings::has(const std::string& key) const {
  for (const GivenSetting& g : items)
    if (g.key == key) return true;
  return false;
}

void GivenSettings::apply_to(DeviceSetup& s) const {
  for (const GivenSetting& g : items) apply_setting(s, g.key + "=" + g.value);
}

namespace {

// The keys that set each refusable field (and the keys its rule involves).
std::vector<std::string> keys_of(proto::ConfigField f) {
  using F = proto::ConfigField;
  switch (f) {
    case F::kWidth: return {"width"};
    case F::kHeight: return {"height"};
    case F::kBaseline: return {"baseline_m"};
    case F::kMisalignment: return {"misalignment_rad"};
    case F::kFocalLength: return {"fu0_px", "fu1_px", "width"};
    case F::kPrincipalPoint: return {"cu0_px", "cu1_px", "width"};
    case F::kNormaliserSigma: return {"normaliser_sigma_rad"};
    case F::kKernelCount:
    case F::kKernelOrder:
    case F::kKernelSigma: return {"kernels"};
    case F::kTau: return {"tau_us"};
    case F::kFramePeriod: return {"frame_period_us"};
    case F::kMaxGap: return {"max_gap_us", "frame_period_us"};
    case F::kGyroGap: return {"gyro_gap_us"};
    case F::kLowTexture: return {"low_texture"};
    case F::kSaturatedPermille: return {"saturated_permille"};
    case F::kStillDistance: return {"still_distance_m"};
    case F::kStillDuration: return {"still_min_us"};
    case F::kLens: return {"lens_cam0", "lens_cam1", "width"};
    default: return {};
  }
}

std::string rule_of_key(const std::string& key) {
  using F = proto::ConfigField;
  if (key == "kernels")
    return "kernels are ORDER:SIGMA_RAD[,...], 1.." + std::to_string(proto::kWireKernels) +
           " of them, orders 0..3, sigmas 0.00873..0.785 rad (0.5..45 deg)";
  if (key == "cam0_upside_down" || key == "cam1_upside_down" || key == "baseline_correction" ||
      key == "gyro_offset_learning" || key == "photometric_balance" || key == "elevation_band" ||
      key == "photometric_match")
    return key + " must be 0 or 1";
  // The field each key sets first (fu and cu before the width their rules involve).
  for (F f : {F::kWidth, F::kHeight, F::kBaseline, F::kMisalignment, F::kFocalLength, F::kPrincipalPoint,
              F::kNormaliserSigma, F::kTau, F::kFramePeriod, F::kMaxGap, F::kGyroGap, F::kLowTexture,
              F::kSaturatedPermille, F::kStillDistance, F::kStillDuration}) {
    const std::vector<std::string> keys = keys_of(f);
    if (!keys.empty() && keys.front() == key) return proto::rule_of(f);
    if (f == F::kFocalLength || f == F::kPrincipalPoint)
      if (std::find(keys.begin(), keys.end(), key) != keys.end() && key != "width") return proto::rule_of(f);
  }
  return "";
}

// validate() after the lens tables are sealed; a table of the wrong length
// is kLens, with seal_lens's reason in *why when asked.
proto::ConfigField validate_setup(DeviceSetup s, std::string* why) {
  try {
    seal_lens(s);
  } catch (const std::runtime_error& e) {
    if (why) {
      *why = e.what();
      const size_t colon = why->find(": ");
      if (colon != std::string::npos) why->erase(0, colon + 2);  // the key is said already
    }
    return proto::ConfigField::kLens;
  }
  return proto::validate(s.config);
}

proto::ConfigField validate_with(const DeviceSetup& base, const GivenSettings& given, const GivenSetting* skip,
                                 std::string* why = nullptr) {
  DeviceSetup s = base;
  for (const GivenSetting& g : given.items)
    if (&g != skip) apply_setting(s, g.key + "=" + g.value);
  return validate_setup(s, why);
}

}  // namespace

std::string check_settings(const DeviceSetup& base, const GivenSettings& given) {
  std::string lens_why;
  const proto::ConfigField f = validate_with(base, given, nullptr, &lens_why);
  if (f == proto::ConfigField::kOk) return "";
  const std::string rule = lens_why.empty() ? std::string(proto::rule_of(f)) : lens_why;
  const std::vector<std::string> keys = keys_of(f);
  // The given setting without which the field is no longer refused, latest first.
  const GivenSetting* blamed = nullptr;
  for (auto it = given.items.rbegin(); it != given.items.rend() && !blamed; ++it) {
    if (std::find(keys.begin(), keys.end(), it->key) == keys.end()) continue;
    if (validate_with(base, given, &*it) != f) blamed = &*it;
  }
  if (!blamed)
    for (auto it = given.items.rbegin(); it != given.items.rend() && !blamed; ++it)
      if (std::find(keys.begin(), keys.end(), it->key) != keys.end()) blamed = &*it;
  auto shown_value = [](const GivenSetting& g) {
    std::string value = g.value;
    if (value.size() > 40) value = value.substr(0, 37) + "...";
    return shown_path(value);  // a control character as \xNN
  };
  if (blamed) {
    // A rule of a key and its partner (keys_of's last: width, frame_period_us)
    // blamed on one of them, 'width = 20: cu must be 0..width - 1 px', left
    // the other's value and line unsaid (cu0_px=19.5 on the line before):
    // the other side's given values are said beside it.
    // (A lens table's reason names the width already.)
    const std::string partner = keys.size() > 1 && lens_why.empty() ? keys.back() : std::string();
    std::string with;
    for (const GivenSetting& g : given.items) {
      const bool other_side = blamed->key == partner
                                  ? g.key != partner && std::find(keys.begin(), keys.end(), g.key) != keys.end()
                                  : !partner.empty() && g.key == partner;
      if (other_side)
        with += std::string(with.empty() ? " (with " : ", ") + g.key + " = " + shown_value(g) +
                (g.where == "command line" ? " on the command line" : " at " + g.where);
    }
    if (!with.empty()) with += ")";
    return blamed->where + ": " + blamed->key + " = " + shown_value(*blamed) + ": " + rule + with;
  }
  std::string names;
  for (const std::string& k : keys) names += (names.empty() ? "" : ", ") + k;
  return (names.empty() ? std::string(proto::to_string(f)) : names) + ": " + rule;
}

void check_settings_offline(const GivenSettings& given) {
  // Keys not given take their most permissive value: the widest frame for
  // fu and cu, the shortest frame period for max_gap_us.
  DeviceSetup base;
  base.config = proto::default_device_config();
  base.config.width = static_cast<uint16_t>(kMaxColumns);
  base.config.fu[0] = base.config.fu[1] = int32_t{1} << fx::kPixelFrac;  // 1 px
  base.config.cu[0] = base.config.cu[1] = 0;
  base.config.frame_period_us = static_cast<uint32_t>(config::range<config::Quantity::kFramePeriod>.lo);
  base.config.max_gap_us = static_cast<uint32_t>(config::range<config::Quantity::kMaxGap>.hi);
  if (!given.has("width")) {  // a table's length cannot be checked without the width
    GivenSettings known;
    for (const GivenSetting& g : given.items)
      if (g.key != "lens_cam0" && g.key != "lens_cam1") known.items.push_back(g);
    const std::string why = check_settings(base, known);
    if (!why.empty()) throw std::runtime_error(why);
    return;
  }
  const std::string why = check_settings(base, given);
  if (!why.empty()) throw std::runtime_error(why);
}

void seal_lens(DeviceSetup& s) {
  proto::DeviceConfig& c = s.config;
  const size_t want = size_t{c.width} + 1;
  c.lens = 0;
  const EdgeOffsetQ15* tables[2] = {nullptr, nullptr};
  for (int i = 0; i < 2; ++i) {
    if (s.lens[i].empty()) continue;
    if (s.lens[i].size() != want) {
      throw std::runtime_error("lens_cam" + std::to_string(i) + ": " + std::to_string(s.lens[i].size()) +
                               (s.lens[i].size() == 1 ? " value" : " values") + ", but width " +
                               std::to_string(c.width) + " needs " + std::to_string(want) + " (one per column edge)");
    }
    c.lens = static_cast<uint8_t>(c.lens | (1u << i));
    tables[i] = s.lens[i].data();
  }
  c.lens_crc = proto::lens_crc(tables, c.lens, static_cast<uint16_t>(want));
}

}  // namespace lumavel::host
