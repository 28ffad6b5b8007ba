// YAML -> Scenario with strict checking: every map's keys are validated so a
// typo is an error naming file and line, never a silently ignored setting.
#include "lumavel/host/render/scenario_loader.hpp"

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/decimal_text.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/lens_distortion.hpp"
#include "lumavel/host/render/photometric_presets.hpp"
#include "lumavel/host/render/view_renderer.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/sensor_yaml.hpp"
#include "lumavel/host/yaml_text.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace lumavel::host::render {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// The brightest a surface is (8-bit white): the patterns' levels lie in 0..kWhite.
constexpr double kWhite = 255;

// A number as a message shows it: the shortest text that reads back as the
// value (format_double), never rounded to 6 digits as a stream prints it:
// 'rate_hz: 10000.0001' said "'rate_hz' = 10000 is out of range [0.1, 10000]",
// a refusal of a value its own rule allows.
std::string shown_number(double v) { return format_double(v); }

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  // A key given twice in one map would be read once and the other value
  // ignored, silently: refused, at every level (as sensor.yaml's keys are).
  //
  // `budget`: the values left to visit. An alias (*NAME) is the anchored node
  // itself, visited again at each use: a dozen lines of aliases of aliases
  // ("billion laughs") made 3e10 visits, and the render hung. Without
  // aliases a file holds at most one value per character, so more visits
  // than that (or a million) can only be aliases multiplying.
  void check_unique_keys(const YAML::Node& n, size_t& budget, size_t limit) const {
    if (budget == 0)
      fail(n, "the file's aliases (*NAME) expand it to more than " + std::to_string(limit) +
                  " values: a scenario holds a few hundred");
    --budget;
    if (n.IsMap()) {
      std::map<std::string, int> seen;
      for (const auto& kv : n) {
        if (!kv.first.IsScalar()) continue;
        const std::string key = kv.first.Scalar();
        const int line = kv.first.Mark().line + 1;
        if (const auto at = seen.find(key); at != seen.end())
          fail(kv.first, "key '" + shown_path(key) + "' is given again (first at line " + std::to_string(at->second) +
                             "): one value per key");
        seen.emplace(key, line);
        // An empty value is a null placed at the next token, lines further on:
        // 'duration_s:' said 'FILE:10: 'duration_s' must be a number', the
        // next key's line. Said at its own; text (a description, a plane's
        // name) may be empty.
        if (kv.second.IsNull() && key != "description" && key != "name")
          fail(kv.first, "'" + shown_path(key) + "' has no value (empty, or null)");
        check_unique_keys(kv.second, budget, limit);
      }
    } else if (n.IsSequence()) {
      for (const auto& e : n) check_unique_keys(e, budget, limit);
    }
  }

  // "FILE:LINE" of a node (FILE alone where yaml-cpp knows no line).
  std::string at(const YAML::Node& n) const {
    std::ostringstream os;
    os << file_;
    if (n.IsDefined() && n.Mark().line >= 0) os << ':' << (n.Mark().line + 1);
    return os.str();
  }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const {
    throw ScenarioError(at(n) + ": " + what);
  }

  void expect_map(const YAML::Node& n, const std::string& where) const {
    if (!n.IsMap()) fail(n, "'" + where + "' must be a map of key: value");
  }

  void check_keys(const YAML::Node& map, const std::string& where,
                  std::initializer_list<const char*> allowed) const {
    expect_map(map, where);
    for (const auto& kv : map) {
      // (as<std::string>() of a list or map key threw yaml-cpp's bare "bad conversion")
      if (!kv.first.IsScalar()) fail(kv.first, "a key in '" + where + "' must be a word, not a list or a map");
      const std::string key = kv.first.Scalar();
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        fail(kv.first, "unknown key '" + shown_path(key) + "' in '" + where + "' (allowed: " + list + ")");
      }
    }
  }

  double to_num(const YAML::Node& n, const std::string& key, double lo, double hi) const {
    if (!n.IsScalar()) fail(n, "'" + key + "' must be a number");
    double v = 0;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      // A number too large for a double is a number (was: ''duration_s' must
      // be a number, got '1e400''), said as sensor.yaml and the tables say it.
      if (read_decimal(n.Scalar()).problem == DecimalText::Problem::kOverflow)
        fail(n, "'" + key + "' = '" + shown_path(n.Scalar()) + "' is beyond the largest number (about 1.8e308)");
      fail(n, "'" + key + "' must be a number, got '" + shown_path(n.Scalar()) + "'");
    }
    if (!std::isfinite(v)) fail(n, "'" + key + "' must be finite");
    // One too small for a double is read as 0 or a subnormal (was:
    // 'duration_s: 1e-400' said ''duration_s' = 0 is out of range'), said
    // as sensor.yaml says it.
    if (read_decimal(n.Scalar()).underflow)
      fail(n, "'" + key + "' = '" + shown_path(n.Scalar()) + "' is " + kNearerZeroThanAnyNumber);
    if (v < lo || v > hi) {
      fail(n, "'" + key + "' = " + shown_number(v) + " is out of range [" + shown_number(lo) + ", " + shown_number(hi) +
                  "]");
    }
    return v;
  }

  double num(const YAML::Node& map, const char* key, double def, double lo, double hi) const {
    const YAML::Node n = map[key];
    if (!n) return def;
    return to_num(n, key, lo, hi);
  }
  double req_num(const YAML::Node& map, const char* key, double lo, double hi,
                 const std::string& where) const {
    const YAML::Node n = map[key];
    if (!n) fail(map, "'" + where + "' needs '" + key + "'");
    return to_num(n, key, lo, hi);
  }

  // A whole number, read as the command lines read theirs (decimal_text.hpp's
  // read_whole): yaml-cpp's as<long long> reads C's base-0 forms ('010' as 8,
  // 0x10 as 16), its as<double> '010' as 10 and '1e3' as 1000, where YAML 1.1
  // readers take 010 as 8 and '--seed 010' is refused. `range`: what follows
  // "must be a whole number" in the message (" in 0..9007199254740992").
  long long whole(const YAML::Node& n, const std::string& key, long long lo, long long hi,
                  const std::string& range) const {
    const WholeText w = n.IsScalar() ? read_whole(n.Scalar()) : WholeText{WholeText::Problem::kNotAWholeNumber, 0};
    if (w.problem == WholeText::Problem::kNone && w.value >= lo && w.value <= hi) return w.value;
    // A list or a map there was said as "not '?'", a value the file does not hold.
    fail(n, "'" + key + "' must be a whole number" + range +
                (w.problem == WholeText::Problem::kLeadingZero ? ", written without a leading zero" : "") + ", not " +
                (n.IsScalar()     ? "'" + shown_path(n.Scalar()) + "'"
                 : n.IsSequence() ? std::string("a list")
                                  : std::string("a map")));
  }

  std::vector<double> list(const YAML::Node& n, const std::string& key, size_t count, double lo,
                           double hi) const {
    if (!n.IsSequence() || (count != 0 && n.size() != count)) {
      fail(n, "'" + key + "' must be a list of " +
                  (count ? std::to_string(count) + " numbers" : std::string("numbers")));
    }
    std::vector<double> out;
    for (const auto& e : n) out.push_back(to_num(e, key, lo, hi));
    return out;
  }

  std::string word(const YAML::Node& map, const char* key, const std::string& def,
                   std::initializer_list<const char*> allowed) const {
    const YAML::Node n = map[key];
    if (!n) return def;
    if (!n.IsScalar()) fail(n, std::string("'") + key + "' must be a word");
    const std::string v = n.Scalar();
    std::string list;
    for (const char* a : allowed) {
      if (v == a) return v;
      list += std::string(list.empty() ? "" : ", ") + a;
    }
    fail(n, std::string("'") + key + "' = '" + shown_path(v) + "' is not one of: " + list);
  }

  // A text value (description, a plane's name): a list or a map there threw
  // yaml-cpp's bare "bad conversion", naming neither the key nor the rule.
  // An empty value ("description:") stays accepted, as empty text.
  std::string text(const YAML::Node& n, const std::string& key) const {
    if (n.IsNull()) return "";
    if (!n.IsScalar()) fail(n, "'" + key + "' must be text, not a list or a map");
    return n.Scalar();
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// The lens must map the field of view one-to-one: along every row and column
// of a grid over the distorted image the undistorted coordinates must settle
// and keep increasing, else the renderer could not find each pixel's ray.
void read_distortion(const Reader& r, const YAML::Node& d, CameraSpec& c) {
  const auto v = r.list(d, "distortion", 4, -10, 10);
  for (int i = 0; i < 4; ++i) c.distortion[static_cast<size_t>(i)] = v[static_cast<size_t>(i)];
  LensDistortion lens;
  lens.k = c.distortion;
  if (lens.none()) return;
  const double tx = std::tan(0.5 * c.hfov_deg * kPi / 180.0), ty = std::tan(0.5 * c.vfov_deg * kPi / 180.0);
  constexpr int kGrid = 41;
  std::vector<double> gx(kGrid * kGrid), gy(kGrid * kGrid);
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const double xd = tx * (2.0 * i / (kGrid - 1) - 1), yd = ty * (2.0 * j / (kGrid - 1) - 1);
      double x, y;
      if (!lens.undistort(xd, yd, x, y))
        r.fail(d, "'distortion' cannot be inverted at the image edge (lens folds over)");
      const double scale = lens_radial_scale(xd, yd, x, y);
      if (!plausible_lens_scale(scale)) {
        char b[200];
        std::snprintf(b, sizeof b,
                      "'distortion' moves a point of the image to %.3g times its pinhole distance from the centre "
                      "(a lens moves it to between %g and %g times): is a coefficient wrong?",
                      scale, kLensMinRadialScale, kLensMaxRadialScale);
        r.fail(d, b);
      }
      gx[static_cast<size_t>(j * kGrid + i)] = x;
      gy[static_cast<size_t>(j * kGrid + i)] = y;
      const bool rising = (i == 0 || x > gx[static_cast<size_t>(j * kGrid + i - 1)]) &&
                          (j == 0 || y > gy[static_cast<size_t>((j - 1) * kGrid + i)]);
      if (!rising) r.fail(d, "'distortion' folds the image over (not one-to-one over the field of view)");
    }
  }
}

// Keys not given keep the preset's value (or the ideal camera's).
void read_camera_response(const Reader& r, const YAML::Node& n, const std::string& where, PhotometricSpec& p) {
  r.check_keys(n, where, {"gain", "black_level", "vignetting", "prnu", "dsnu", "column_gain", "column_offset",
                          "gamma", "auto_exposure"});
  p.gain = r.num(n, "gain", p.gain, 0.05, 20);
  p.black_level = r.num(n, "black_level", p.black_level, 0, 128);
  if (const YAML::Node v = n["vignetting"]) {
    const auto c = r.list(v, "vignetting", 2, -2, 2);
    // 1 + v1 x + v2 x^2 over x = r^2 in [0, 1]: extremes at the ends or the vertex.
    double lo = std::min(1.0, 1 + c[0] + c[1]), hi = std::max(1.0, 1 + c[0] + c[1]);
    if (c[1] != 0.0) {
      const double x = -c[0] / (2 * c[1]);
      if (x > 0 && x < 1) {
        lo = std::min(lo, 1 + c[0] * x + c[1] * x * x);
        hi = std::max(hi, 1 + c[0] * x + c[1] * x * x);
      }
    }
    if (lo < 0.05 || hi > 2) {
      r.fail(v, "'vignetting' = [" + shown_number(c[0]) + ", " + shown_number(c[1]) +
                    "] gives 1 + v1 r^2 + v2 r^4 from " + shown_number(lo) + " to " + shown_number(hi) +
                    " over the image; it must stay within [0.05, 2]");
    }
    p.vignetting[0] = c[0];
    p.vignetting[1] = c[1];
  }
  p.prnu = r.num(n, "prnu", p.prnu, 0, 0.2);
  p.dsnu = r.num(n, "dsnu", p.dsnu, 0, 20);
  p.column_gain = r.num(n, "column_gain", p.column_gain, 0, 0.2);
  p.column_offset = r.num(n, "column_offset", p.column_offset, 0, 20);
  p.gamma = r.num(n, "gamma", p.gamma, 0.2, 5);
  if (const YAML::Node ae = n["auto_exposure"]) {
    r.check_keys(ae, "auto_exposure", {"sigma", "interval_s"});
    p.auto_exposure.sigma = r.num(ae, "sigma", p.auto_exposure.sigma, 0, 1);
    p.auto_exposure.interval_s = r.num(ae, "interval_s", p.auto_exposure.interval_s, 0.05, 1e4);
  }
}

void read_photometric(const Reader& r, const YAML::Node& n, CameraSpec& c) {
  r.check_keys(n, "photometric", {"preset", "cam0", "cam1"});
  if (const YAML::Node pn = n["preset"]) {
    if (!pn.IsScalar()) r.fail(pn, "'preset' must be a word");
    const PhotometricPreset* p = find_photometric_preset(pn.Scalar());
    if (!p) r.fail(pn, "'preset' = '" + shown_path(pn.Scalar()) + "' is not one of: " + photometric_preset_names());
    c.photometric = p->cams;
    c.photometric_preset = p->name;
  }
  if (const YAML::Node c0 = n["cam0"]) read_camera_response(r, c0, "cam0", c.photometric[0]);
  if (const YAML::Node c1 = n["cam1"]) read_camera_response(r, c1, "cam1", c.photometric[1]);
}

void read_camera(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "camera", {"resolution", "fov_deg", "rate_hz", "exposure", "baseline_m",
                             "misalignment_deg", "look", "ahead", "rig_yaw_deg", "first_frame_s",
                             "noise_sigma", "distortion", "photometric"});
  CameraSpec& c = s.camera;
  if (const YAML::Node rn = n["resolution"]) {
    if (!rn.IsSequence() || rn.size() != 2) r.fail(rn, "'resolution' must be a list of 2 numbers");
    // Pixels as --resolution reads them (was: 'resolution: [040, 30]' rendered
    // at 40 columns, where '--resolution 040x30' is refused).
    const std::string range = " in 1.." + std::to_string(static_cast<long long>(kMaxImageSide)) + " (pixels)";
    const double v[2] = {static_cast<double>(r.whole(rn[0], "resolution", 1, static_cast<long long>(kMaxImageSide), range)),
                         static_cast<double>(r.whole(rn[1], "resolution", 1, static_cast<long long>(kMaxImageSide), range))};
    // (was: rendered, for hours at 8192x8192, then refused by run's check)
    if (const std::string why = why_too_many_pixels(v[0], v[1]); !why.empty())
      r.fail(n["resolution"], "'resolution' = [" + std::to_string(static_cast<long>(v[0])) + ", " +
                                  std::to_string(static_cast<long>(v[1])) + "] " + why);
    c.width = static_cast<int>(v[0]);
    c.height = static_cast<int>(v[1]);
  }
  if (n["fov_deg"]) {
    const auto v = r.list(n["fov_deg"], "fov_deg", 2, 0.1, 170);
    c.hfov_deg = v[0];
    c.vfov_deg = v[1];
  }
  c.rate_hz = r.num(n, "rate_hz", c.rate_hz, 0.1, 10000);
  c.exposure_frames = r.num(n, "exposure", c.exposure_frames, 0, kMaxExposureFrames);
  c.baseline_m = r.num(n, "baseline_m", c.baseline_m, 0, 10);
  c.misalignment_deg = r.num(n, "misalignment_deg", c.misalignment_deg, -45, 45);
  c.look = r.word(n, "look", "left", {"left", "right"}) == "left" ? LookSide::Left : LookSide::Right;
  c.cam1_ahead = r.word(n, "ahead", "cam1", {"cam0", "cam1"}) == "cam1";
  c.rig_yaw_deg = r.num(n, "rig_yaw_deg", c.rig_yaw_deg, -80, 80);
  // (before 0, frame times would precede the recording's start: negative, or wrapped below start_ns)
  c.first_frame_s = r.num(n, "first_frame_s", c.first_frame_s, 0, 1e6);
  s.pixel_noise_sigma = r.num(n, "noise_sigma", s.pixel_noise_sigma, 0, 255);
  if (const YAML::Node d = n["distortion"]) read_distortion(r, d, c);
  if (const YAML::Node p = n["photometric"]) read_photometric(r, p, c);
}

void read_segment(const Reader& r, const YAML::Node& n, SegmentSpec& g) {
  r.check_keys(n, "segment", {"type", "duration_s", "speed", "profile", "radius_m", "turn"});
  const std::string type = r.word(n, "type", "", {"straight", "arc"});
  if (type.empty()) r.fail(n, "segment needs 'type' (straight or arc)");
  g.kind = type == "arc" ? SegmentKind::Arc : SegmentKind::Straight;
  g.duration_s = r.req_num(n, "duration_s", 1e-6, 1e6, "segment");
  const YAML::Node sp = n["speed"];
  if (!sp) r.fail(n, "segment needs 'speed' (a number or [start, end])");
  if (sp.IsSequence()) {
    const auto v = r.list(sp, "speed", 2, -1000, 1000);
    g.v0 = v[0];
    g.v1 = v[1];
  } else {
    g.v0 = g.v1 = r.to_num(sp, "speed", -1000, 1000);
  }
  g.profile = r.word(n, "profile", "linear", {"linear", "smooth"}) == "smooth"
                  ? SpeedProfile::Smooth
                  : SpeedProfile::Linear;
  if (g.kind == SegmentKind::Arc) {
    const double radius = r.req_num(n, "radius_m", 1e-3, 1e9, "arc segment");
    const std::string turn = r.word(n, "turn", "", {"left", "right"});
    if (turn.empty()) r.fail(n, "arc segment needs 'turn' (left or right)");
    g.curvature = (turn == "left" ? 1.0 : -1.0) / radius;
  } else if (n["radius_m"] || n["turn"]) {
    r.fail(n, "'radius_m' and 'turn' only apply to arc segments");
  }
}

void read_trajectory(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "trajectory", {"start", "segments"});
  TrajectorySpec& t = s.trajectory;
  if (const YAML::Node st = n["start"]) {
    r.check_keys(st, "start", {"x", "y", "z", "heading_deg"});
    t.x0 = r.num(st, "x", 0, -1e6, 1e6);
    t.y0 = r.num(st, "y", 0, -1e6, 1e6);
    t.z = r.num(st, "z", 0, -1e6, 1e6);
    t.heading0_deg = r.num(st, "heading_deg", 0, -360, 360);
  }
  const YAML::Node segs = n["segments"];
  if (!segs || !segs.IsSequence() || segs.size() == 0)
    r.fail(segs ? segs : n, "'trajectory' needs a non-empty list 'segments'");
  for (const auto& e : segs) {
    SegmentSpec g;
    read_segment(r, e, g);
    t.segments.push_back(g);
  }
}

std::string resolve_path(const std::string& file, const std::string& base_dir) {
  if (!file.empty() && file[0] == '/') return file;
  return base_dir + "/" + file;
}

void read_pattern(const Reader& r, const YAML::Node& n, PatternSpec& p,
                  const std::string& base_dir) {
  r.expect_map(n, "pattern");
  const std::string type = r.word(n, "type", "", {"uniform", "sinusoid", "checker", "photo"});
  if (type == "uniform") {
    r.check_keys(n, "pattern", {"type", "value"});
    p.kind = PatternKind::Uniform;
    p.value = r.num(n, "value", p.value, 0, kWhite);
  } else if (type == "sinusoid") {
    r.check_keys(n, "pattern", {"type", "mean", "amplitude", "period_m", "phase_deg", "combine"});
    p.kind = PatternKind::Sinusoid;
    p.mean = r.num(n, "mean", p.mean, 0, kWhite);
    p.amplitude = r.num(n, "amplitude", p.amplitude, 0, kWhite);
    // The pattern spans mean - amplitude .. mean + amplitude (sum or product):
    // below 0 it was clipped to black, silently (flattened troughs, another
    // mean). A brightness cannot be negative: refused.
    const YAML::Node blamed = n["amplitude"] ? n["amplitude"] : n["mean"] ? n["mean"] : n;
    if (p.amplitude > p.mean) {
      r.fail(blamed,
             "sinusoid 'amplitude' = " + shown_number(p.amplitude) +
                 " is larger than its 'mean' = " + shown_number(p.mean) +
                 ": the brightness, mean - amplitude at the troughs, would go below 0 and be clipped to black; a "
                 "brightness cannot be negative, so amplitude must be at most the mean");
    }
    // Above 255 it was clipped to white, silently (flattened crests, another mean).
    if (p.mean + p.amplitude > kWhite) {
      r.fail(blamed, "sinusoid 'mean' = " + shown_number(p.mean) + " plus its 'amplitude' = " +
                         shown_number(p.amplitude) + " is " + shown_number(p.mean + p.amplitude) +
                         ": the brightness, mean + amplitude at the crests, would go above " + shown_number(kWhite) +
                         " (white) and be clipped; amplitude must be at most " + shown_number(kWhite) + " - mean");
    }
    if (n["period_m"]) {
      const auto v = r.list(n["period_m"], "period_m", 2, 1e-4, 1e6);
      p.period_h_m = v[0];
      p.period_v_m = v[1];
    }
    if (n["phase_deg"]) {
      const auto v = r.list(n["phase_deg"], "phase_deg", 2, -360, 360);
      p.phase_h_deg = v[0];
      p.phase_v_deg = v[1];
    }
    p.product = r.word(n, "combine", "sum", {"sum", "product"}) == "product";
  } else if (type == "checker") {
    r.check_keys(n, "pattern", {"type", "square_m", "low", "high"});
    p.kind = PatternKind::Checker;
    p.square_m = r.num(n, "square_m", p.square_m, 1e-4, 1e6);
    p.low = r.num(n, "low", p.low, 0, kWhite);
    p.high = r.num(n, "high", p.high, 0, kWhite);
  } else if (type == "photo") {
    r.check_keys(n, "pattern", {"type", "file", "size_m", "tiling", "offset_m"});
    p.kind = PatternKind::Photo;
    const YAML::Node f = n["file"];
    if (!f || !f.IsScalar()) r.fail(n, "photo pattern needs 'file'");
    // An empty name resolved to the scenario's own folder: 'photo 'DIR/' is a
    // folder, not a file', a name the file does not hold.
    if (f.Scalar().empty()) r.fail(f, "photo 'file' is empty: it names the photo (relative to the scenario file)");
    // "a.png\0junk" (a YAML escape) would open a.png (was: rendered, exit 0).
    if (const std::string why = why_nul_in_name(f.Scalar()); !why.empty()) r.fail(f, "photo file name " + why);
    p.file = resolve_path(f.Scalar(), base_dir);
    p.file_at = r.at(f);
    if (const std::string why = why_not_a_file(p.file); !why.empty()) r.fail(f, "photo '" + shown_path(p.file) + "' " + why);
    if (!std::ifstream(p.file)) r.fail(f, "cannot open photo '" + shown_path(p.file) + "'");
    if (!n["size_m"]) r.fail(n, "photo pattern needs 'size_m: [width, height]'");
    const auto v = r.list(n["size_m"], "size_m", 2, 1e-4, 1e6);
    p.width_m = v[0];
    p.height_m = v[1];
    const std::string tiling = r.word(n, "tiling", "none", {"none", "mirror", "repeat"});
    p.tiling = tiling == "mirror" ? Tiling::Mirror : tiling == "repeat" ? Tiling::Repeat : Tiling::None;
    if (n["offset_m"]) {
      const auto o = r.list(n["offset_m"], "offset_m", 2, -1e6, 1e6);
      p.offset_h_m = o[0];
      p.offset_v_m = o[1];
    }
  } else {
    r.fail(n, "pattern needs 'type' (uniform, sinusoid, checker or photo)");
  }
}

void read_scene(const Reader& r, const YAML::Node& n, Scenario& s, const std::string& base_dir) {
  r.check_keys(n, "scene", {"background", "planes"});
  s.background = r.num(n, "background", s.background, 0, kWhite);
  const YAML::Node planes = n["planes"];
  if (!planes) return;
  if (!planes.IsSequence()) r.fail(planes, "'planes' must be a list");
  if (planes.size() > static_cast<size_t>(kMaxScenePlanes))
    r.fail(planes, "at most " + std::to_string(kMaxScenePlanes) + " planes");
  for (const auto& e : planes) {
    r.check_keys(e, "plane", {"name", "from", "to", "z", "pattern"});
    PlaneSpec p;
    p.name = e["name"] ? r.text(e["name"], "name") : "plane" + std::to_string(s.planes.size());
    if (!e["from"] || !e["to"] || !e["z"]) r.fail(e, "plane needs 'from', 'to' and 'z'");
    const auto a = r.list(e["from"], "from", 2, -1e6, 1e6);
    const auto b = r.list(e["to"], "to", 2, -1e6, 1e6);
    const auto z = r.list(e["z"], "z", 2, -1e6, 1e6);
    if (std::hypot(b[0] - a[0], b[1] - a[1]) < 1e-6) r.fail(e["to"], "'to' equals 'from'");
    if (z[1] <= z[0]) r.fail(e["z"], "'z' must be [bottom, top] with top > bottom");
    p.from[0] = a[0];
    p.from[1] = a[1];
    p.to[0] = b[0];
    p.to[1] = b[1];
    p.z_min = z[0];
    p.z_max = z[1];
    if (!e["pattern"]) r.fail(e, "plane needs 'pattern'");
    read_pattern(r, e["pattern"], p.pattern, base_dir);
    s.planes.push_back(p);
  }
}

void read_lighting(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "lighting", {"flicker_hz", "flicker_amplitude", "flicker_phase_deg", "dark"});
  LightingSpec& l = s.lighting;
  l.flicker_hz = r.num(n, "flicker_hz", 0, 0, 1e6);
  l.flicker_amplitude = r.num(n, "flicker_amplitude", 0, 0, 1);
  l.flicker_phase_deg = r.num(n, "flicker_phase_deg", 0, -360, 360);
  if (const YAML::Node d = n["dark"]) {
    if (!d.IsSequence()) r.fail(d, "'dark' must be a list of [start_s, end_s]");
    for (const auto& e : d) {
      // Each element is an interval: 'dark: [3, 3.5]' (one interval without
      // its brackets) was refused as "'dark' must be a list of 2 numbers", a
      // rule the value meets. Said with the element that is no interval.
      if (!e.IsSequence() || e.size() != 2)
        r.fail(e, "'dark' must be a list of [start_s, end_s] intervals (e.g. dark: [[3, 3.5]]): an element is " +
                      (e.IsScalar() ? "'" + shown_path(e.Scalar()) + "', not an interval"
                       : e.IsSequence() ? "a list of " + std::to_string(e.size()) + " numbers, not 2"
                                        : std::string("a map, not an interval")));
      const auto v = r.list(e, "dark", 2, -kInf, kInf);
      if (v[1] <= v[0]) r.fail(e, "dark interval must be [start_s, end_s] with end > start");
      l.dark.emplace_back(v[0], v[1]);
    }
  }
}

void read_imu(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "imu", {"rate_hz", "offset_s", "gyro_noise_density", "gyro_random_walk",
                          "gyro_bias_deg_s", "accel_noise_density"});
  ImuSpec& m = s.imu;
  m.rate_hz = r.num(n, "rate_hz", m.rate_hz, 1, 100000);
  // Bounded as first_frame_s is: the first sample's time is rounded to int64
  // nanoseconds, and 1e300 s overflowed it (the sample loop then stepped
  // from the wrapped time for ever: the render hung).
  m.offset_s = r.num(n, "offset_s", m.offset_s, -1e6, 1e6);
  m.gyro_noise_density = r.num(n, "gyro_noise_density", 0, 0, kMaxGyroNoiseDensity);
  m.gyro_random_walk = r.num(n, "gyro_random_walk", 0, 0, kMaxGyroRandomWalk);
  m.gyro_bias_z = r.num(n, "gyro_bias_deg_s", 0, -1000, 1000) * kPi / 180.0;
  m.accel_noise_density = r.num(n, "accel_noise_density", 0, 0, 100);
}

void read_vibration(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "vibration", {"pitch_deg", "roll_deg", "heave_m", "frequency_hz"});
  VibrationSpec& v = s.vibration;
  v.pitch_rms_deg = r.num(n, "pitch_deg", 0, 0, kMaxVibrationAngleDeg);
  v.roll_rms_deg = r.num(n, "roll_deg", 0, 0, kMaxVibrationAngleDeg);
  v.heave_rms_m = r.num(n, "heave_m", 0, 0, kMaxVibrationHeaveM);
  // No default band: how fast a rig shakes is the vehicle's, said in the file.
  const YAML::Node f = n["frequency_hz"];
  if (!f) r.fail(n, "'vibration' needs 'frequency_hz: [low, high]' (Hz)");
  const auto band = r.list(f, "frequency_hz", 2, kMinVibrationHz, kMaxVibrationHz);
  if (band[1] < band[0])
    r.fail(f, "'frequency_hz' = [" + shown_number(band[0]) + ", " + shown_number(band[1]) +
                  "] must be [low, high] with low <= high");
  v.freq_lo_hz = band[0];
  v.freq_hi_hz = band[1];
}

void read_drops(const Reader& r, const YAML::Node& n, Scenario& s) {
  r.check_keys(n, "drops", {"frames", "rate"});
  if (const YAML::Node f = n["frames"]) {
    // A frame beyond the recording was ignored and one listed twice counted
    // once, silently: refused, so the list says what the recording lacks.
    // The recording's frames are those the renderer makes (FrameRenderer::
    // frame_count: mid-exposure first_frame_s + i / rate_hz, period rounded
    // to nanoseconds, before duration_s), of the scenario as written (a
    // --duration override may shorten it: drops past its end then just fall away).
    const double period_ns = static_cast<double>(std::llround(1e9 / s.camera.rate_hz));
    const double first_ns = static_cast<double>(std::llround(s.camera.first_frame_s * 1e9));
    const double frames = std::max(0.0, std::ceil((s.duration_s * 1e9 - first_ns) / period_ns));
    std::map<int, int> line_of;
    if (!f.IsSequence()) r.fail(f, "'frames' must be a list of numbers");
    for (size_t k = 0; k < f.size(); ++k) {
      const YAML::Node e = f[k];
      // Frame numbers as the seed's (was: 'frames: [010]' dropped frame 10).
      const double v = static_cast<double>(r.whole(e, "frames", 0, 1000000000, " in 0..1000000000 (frame numbers)"));
      if ((first_ns + v * period_ns) * 1e-9 >= s.duration_s) {
        r.fail(e, "'frames' = " + std::to_string(static_cast<long long>(v)) +
                      " is not a frame of the recording: frame numbers must be below its frame count, " +
                      std::to_string(static_cast<long long>(frames)) + " (duration_s " + shown_number(s.duration_s) +
                      " s x rate_hz " + shown_number(s.camera.rate_hz) + " Hz" +
                      (s.camera.first_frame_s != 0 ? ", from first_frame_s" : "") + ")");
      }
      const int i = static_cast<int>(v);
      const int line = e.Mark().line + 1;
      if (const auto at = line_of.find(i); at != line_of.end())
        r.fail(e, "'frames' lists frame " + std::to_string(i) + " again (first at line " + std::to_string(at->second) +
                      "): each frame once");
      line_of.emplace(i, line);
      s.dropped_frames.push_back(i);
    }
  }
  s.drop_rate = r.num(n, "rate", 0, 0, 1);
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& name,
                        const std::string& base_dir) {
  // The file's name as every message shows it (was: a scenario named
  // 'sc<ESC>[2J.yaml' sent the escape sequence to the terminal with each refusal).
  const std::string shown = shown_path(name);
  const Reader r(shown);
  if (const yaml_text::BadLine bad = yaml_text::why_bad_line(text); bad.line != 0)
    throw ScenarioError(shown + ":" + std::to_string(bad.line) + ": " + bad.why);
  // YAML::Load reads the first document only: whatever follows a '---' (or a
  // '...' end marker) after some content was ignored, silently, and the
  // render made from the first part. Refused, as in a sensor.yaml (scanned
  // in the text: yaml-cpp's LoadAll can loop on malformed input).
  if (const yaml_text::NotOneDocument bad = yaml_text::why_not_one_document(text); bad.line != 0)
    throw ScenarioError(shown + ":" + std::to_string(bad.line) + ": " + bad.why +
                        ": a scenario is one map of KEY: VALUE lines");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own words for it are "bad file" (was: 'YAML syntax: bad file', no rule said).
    throw ScenarioError(shown + ":" + std::to_string(e.mark.line + 1) + ": YAML nested " + std::to_string(e.depth()) +
                        " levels deep, as deep as the YAML reader goes: a scenario is one map of KEY: VALUE lines "
                        "(host_sim/scenarios/README.md)");
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(shown + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax: " + e.msg +
                        yaml_text::tab_indent_note(text, e.mark.line + 1));
  }
  if (root.IsNull())
    throw ScenarioError(shown + ": " + yaml_text::why_null_document(text) +
                        ": a scenario holds KEY: VALUE lines (host_sim/scenarios/README.md)");
  if (!root.IsMap())
    throw ScenarioError(shown + ":" + std::to_string(root.Mark().line + 1) +
                        ": a scenario must be a YAML map of KEY: VALUE lines (host_sim/scenarios/README.md)");
  try {
    const size_t limit = std::max<size_t>(1000000, text.size());
    size_t budget = limit;
    r.check_unique_keys(root, budget, limit);
    r.check_keys(root, "scenario", {"description", "duration_s", "seed", "start_ns",
                                    "groundtruth_rate_hz", "camera", "trajectory", "scene",
                                    "lighting", "imu", "drops", "vibration"});
    Scenario s;
    s.file = name;
    if (root["description"]) s.description = r.text(root["description"], "description");
    s.duration_s = r.req_num(root, "duration_s", kMinDurationS, kMaxDurationS, "scenario");
    // The seed as --seed reads it (was: 'seed: 010' rendered with seed 10, '1e3'
    // with 1000, where '--seed 010' is refused).
    if (const YAML::Node n = root["seed"]) s.seed = static_cast<uint64_t>(r.whole(n, "seed", 0, 9007199254740992LL, " in 0..9007199254740992"));
    else s.seed = 1;
    // Timestamps start_ns + up to 1e6 s stay within the format's signed 64-bit nanoseconds.
    constexpr long long kMaxStartNs = 4000000000000000000LL;
    if (const YAML::Node n = root["start_ns"])
      s.start_ns = r.whole(n, "start_ns", 0, kMaxStartNs,
                           " of nanoseconds in 0..4e18 (timestamps must stay within signed 64 bits)");
    s.groundtruth_rate_hz = r.num(root, "groundtruth_rate_hz", 200, 1, 100000);
    if (root["camera"]) read_camera(r, root["camera"], s);
    if (!root["trajectory"]) r.fail(root, "scenario needs 'trajectory'");
    read_trajectory(r, root["trajectory"], s);
    if (root["scene"]) read_scene(r, root["scene"], s, base_dir);
    if (root["lighting"]) read_lighting(r, root["lighting"], s);
    if (root["imu"]) read_imu(r, root["imu"], s);
    if (root["drops"]) read_drops(r, root["drops"], s);
    if (root["vibration"]) read_vibration(r, root["vibration"], s);
    return s;
  } catch (const YAML::Exception& e) {
    throw ScenarioError(shown + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

Scenario load_scenario(const std::string& path) {
  if (const std::string why = why_not_a_file(path, "scenario file"); !why.empty())
    throw ScenarioError(shown_path(path) + ": " + why);
  if (const std::string why = why_too_big_for_text(path, "a scenario holds a few hundred lines"); !why.empty())
    throw ScenarioError(shown_path(path) + ": " + why);
  std::ifstream in(path);
  if (!in) throw ScenarioError(shown_path(path) + ": cannot open scenario file: " + std::strerror(errno));
  std::stringstream ss;
  ss << in.rdbuf();
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
  return parse_scenario(ss.str(), path, dir.empty() ? "/" : dir);
}

void apply_overrides(Scenario& s, const Overrides& o) {
  if (o.width > 0 && o.height > 0) {
    s.camera.width = o.width;
    s.camera.height = o.height;
  }
  if (o.exposure_frames >= 0) s.camera.exposure_frames = o.exposure_frames;
  if (o.seed >= 0) s.seed = static_cast<uint64_t>(o.seed);
  if (o.duration_s > 0) s.duration_s = o.duration_s;
  if (!o.camera_mismatch.empty()) {
    const PhotometricPreset* p = find_photometric_preset(o.camera_mismatch);
    if (!p)
      throw ScenarioError("camera mismatch preset '" + shown_path(o.camera_mismatch) +
                          "' is not one of: " + photometric_preset_names());
    s.camera.photometric = p->cams;
    s.camera.photometric_preset = p->name;
  }
}

void check_render_size(const Scenario& s) {
  // From the stream's first sample (or scenario time 0, whichever is earlier) to the end.
  const auto check = [&s](const char* what, const char* rate_key, double rate_hz, double from_s) {
    const double n = std::floor((s.duration_s - std::min(from_s, 0.0)) * rate_hz) + 1;
    if (n <= kMaxRenderSamples) return;
    throw ScenarioError(shown_path(s.file) + ": " + rate_key + " = " + shown_number(rate_hz) + " Hz for duration_s = " +
                        shown_number(s.duration_s) + " s is " + std::to_string(static_cast<long long>(n)) + " " + what +
                        ": a render makes at most " + std::to_string(static_cast<long long>(kMaxRenderSamples)) +
                        " (shorten the duration or lower the rate)");
  };
  check("frame pairs", "camera rate_hz", s.camera.rate_hz, s.camera.first_frame_s);
  check("gyro samples", "imu rate_hz", s.imu.rate_hz, s.imu.offset_s);
  check("ground-truth samples", "groundtruth_rate_hz", s.groundtruth_rate_hz, 0);
}

}  // namespace lumavel::host::render
