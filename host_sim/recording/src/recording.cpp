#include "lumavel/host/recording.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/frame_glitch.hpp"
#include "lumavel/host/gyro_glitch.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_layout.hpp"
#include "lumavel/host/rig.hpp"

namespace lumavel::host {
namespace {

bool is_dir(const std::string& p) { return why_not_a_folder(p).empty(); }

double median_interval_s(const std::vector<uint64_t>& t) {
  if (t.size() < 2) return 0;
  std::vector<uint64_t> d;
  d.reserve(t.size() - 1);
  for (size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return static_cast<double>(d[d.size() / 2]) * 1e-9;
}

struct CamRows {
  std::string csv;
  std::vector<CsvRow> rows;
};

// A frame's name is read below cam*/data/: an absolute name or a '..'
// component would read (and pass off as a frame) any file on the machine.
bool leaves_data_folder(const std::string& name) {
  if (name[0] == '/') return true;
  for (size_t at = 0; at <= name.size();) {
    const size_t end = std::min(name.find('/', at), name.size());
    if (name.compare(at, end - at, "..") == 0 && end - at == 2) return true;
    at = end + 1;
  }
  return false;
}

// `named`: the frame files of both cameras (a frame file is one frame: a
// second row naming it, or naming a link to it, in either table is a damaged
// table).
CamRows read_cam_rows(const std::string& root, int cam, FrameNames& named) {
  CamRows c;
  const std::string dir = root + "/" + layout::kCamDir[cam];
  c.csv = dir + "/data.csv";
  c.rows = read_csv_table(c.csv, layout::cam_columns());
  named.next_table(c.csv);
  for (CsvRow& r : c.rows) {
    std::string& name = r.fields[0];
    if (name.empty()) throw recording_error_at(c.csv, r.line, "empty filename");
    if (const std::string why = why_nul_in_name(name); !why.empty())
      throw recording_error_at(c.csv, r.line, "filename " + why);
    if (leaves_data_folder(name))
      throw recording_error_at(c.csv, r.line,
                               "filename '" + shown_path(name) + "' leaves " + layout::kCamDir[cam] +
                                   "/data/ (names are relative to it, with no '..' and no leading '/')");
    const std::string path = dir + "/data/" + name;
    if (const std::string why = why_not_a_file(path); !why.empty())
      throw recording_error_at(c.csv, r.line, "image file " + shown_path(path) + " " + why);
    if (const std::string why = named.why_repeated(name, r.line, path); !why.empty())
      throw recording_error_at(c.csv, r.line, why);
    name = path;
  }
  return c;
}

// cam0 and cam1 are triggered together: every row must have a partner with
// the same timestamp in the other camera.
std::vector<FramePairEntry> pair_frames(const CamRows& c0, const CamRows& c1) {
  std::vector<FramePairEntry> out;
  out.reserve(c0.rows.size());
  size_t i = 0, j = 0;
  while (i < c0.rows.size() || j < c1.rows.size()) {
    const bool have0 = i < c0.rows.size(), have1 = j < c1.rows.size();
    if (have0 && have1 && c0.rows[i].t_ns == c1.rows[j].t_ns) {
      FramePairEntry e;
      e.t_ns = c0.rows[i].t_ns;
      e.path[0] = c0.rows[i].fields[0];
      e.path[1] = c1.rows[j].fields[0];
      out.push_back(std::move(e));
      ++i;
      ++j;
    } else if (have0 && (!have1 || c0.rows[i].t_ns < c1.rows[j].t_ns)) {
      throw recording_error_at(c0.csv, c0.rows[i].line,
                               "unpaired frame: timestamp " + std::to_string(c0.rows[i].t_ns) + " has no row in " +
                                   shown_path(c1.csv));
    } else {
      throw recording_error_at(c1.csv, c1.rows[j].line,
                               "unpaired frame: timestamp " + std::to_string(c1.rows[j].t_ns) + " has no row in " +
                                   shown_path(c0.csv));
    }
  }
  return out;
}

}  // namespace

std::string why_implausible_imu_value(size_t column, double v, const std::string& text) {
  const double limit = column < 3 ? layout::kImuMaxRateRadps : layout::kImuMaxAccelMps2;
  if (std::fabs(v) <= limit) return "";
  return text + " is beyond +-" + format_double(limit) + ", more than any IMU measures: a corrupt value";
}

std::string why_implausible_groundtruth_value(size_t column, double v) {
  // Positions, velocities and biases each within their bound (a quaternion's
  // norm is a rule of the four together, why_not_unit_quaternion).
  if (column < 3) return why_implausible_position(v);
  if (column >= 7 && column < 10) return why_implausible_speed(v);
  if (column < 10) return "";
  const double limit = column < 13 ? layout::kImuMaxRateRadps : layout::kImuMaxAccelMps2;
  if (std::fabs(v) <= limit) return "";
  return format_double(v) + " is beyond +-" + format_double(limit) + ", more than any IMU measures: a corrupt bias";
}

void check_sample_values(const Recording& rec) {
  const std::string imu_csv = rec.root + "/" + layout::kImuDir + "/data.csv";
  for (size_t i = 0; i < rec.imu_samples.size(); ++i)
    for (size_t k = 0; k < 6; ++k) {
      const double v = k < 3 ? rec.imu_samples[i].w[k] : rec.imu_samples[i].a[k - 3];
      if (const std::string why = why_implausible_imu_value(k, v, format_double(v)); !why.empty())
        throw recording_error_at(imu_csv, static_cast<long>(i) + 2, "column '" + layout::imu_columns()[k] + "': " + why);
    }
  const std::string gt_csv = rec.root + "/" + layout::kGroundTruthDir + "/data.csv";
  for (size_t i = 0; i < rec.groundtruth.size(); ++i) {
    const GroundTruthSample& g = rec.groundtruth[i];
    const double v[16] = {g.p[0], g.p[1], g.p[2], g.q[0], g.q[1], g.q[2], g.q[3], g.v[0],
                          g.v[1], g.v[2], g.bw[0], g.bw[1], g.bw[2], g.ba[0], g.ba[1], g.ba[2]};
    for (size_t k = 0; k < 16; ++k)
      if (const std::string why = why_implausible_groundtruth_value(k, v[k]); !why.empty())
        throw recording_error_at(gt_csv, static_cast<long>(i) + 2,
                                 "column '" + layout::groundtruth_columns()[k] + "': " + why);
  }
}

namespace {

std::vector<ImuSample> read_imu(const std::string& csv) {
  std::vector<ImuSample> out;
  for_each_csv_row(csv, layout::imu_columns(), [&](const CsvRow& r) {
    ImuSample s;
    s.t_ns = r.t_ns;
    for (int k = 0; k < 6; ++k) {
      const std::string& column = layout::imu_columns()[static_cast<size_t>(k)];
      const double v = parse_finite(r.fields[static_cast<size_t>(k)], csv, r.line, column);
      if (const std::string why = why_implausible_imu_value(static_cast<size_t>(k), v, r.fields[static_cast<size_t>(k)]);
          !why.empty())
        throw recording_error_at(csv, r.line, "column '" + column + "': " + why);
      (k < 3 ? s.w[k] : s.a[k - 3]) = v;
    }
    out.push_back(s);
  });
  return out;
}

// The samples, and in `line` each one's line of the file.
std::vector<GroundTruthSample> read_groundtruth(const std::string& csv, std::vector<long>& line) {
  std::vector<GroundTruthSample> out;
  for_each_csv_row(csv, layout::groundtruth_columns(), [&](const CsvRow& r) {
    line.push_back(r.line);
    double v[16];
    for (size_t k = 0; k < 16; ++k) {
      const std::string& column = layout::groundtruth_columns()[k];
      v[k] = parse_finite(r.fields[k], csv, r.line, column);
      if (const std::string why = why_implausible_groundtruth_value(k, v[k]); !why.empty())
        throw recording_error_at(csv, r.line, "column '" + column + "': " + why);
    }
    GroundTruthSample g;
    g.t_ns = r.t_ns;
    for (int k = 0; k < 3; ++k) {
      g.p[k] = v[k];
      g.v[k] = v[7 + k];
      g.bw[k] = v[10 + k];
      g.ba[k] = v[13 + k];
    }
    for (int k = 0; k < 4; ++k) g.q[k] = v[3 + k];
    const double n = std::sqrt(g.q[0] * g.q[0] + g.q[1] * g.q[1] + g.q[2] * g.q[2] + g.q[3] * g.q[3]);
    if (const std::string why = why_not_unit_quaternion(n); !why.empty())
      throw recording_error_at(csv, r.line, "q_RS " + why);
    out.push_back(g);
  });
  return out;
}

// The first frame of each camera must match its sensor.yaml; later frames are
// checked as they are decoded.
void check_first_frame(const std::string& image, int cam, const CameraSensor& s, const std::string& yaml) {
  const GrayImage img = read_gray_image(image, s.width, s.height);  // of another size: not decoded
  if (img.width != s.width || img.height != s.height)
    throw recording_error_in(image, "frame 0 of " + std::string(layout::kCamDir[cam]) + " is " +
                                        std::to_string(img.width) + "x" + std::to_string(img.height) + ", but " +
                                        shown_path(yaml) + " says resolution [" + std::to_string(s.width) + ", " +
                                        std::to_string(s.height) + "]");
}

// Both cameras are binned to one working size: their sensors must match.
void check_same_resolution(const Recording& rec, const std::string yaml[2]) {
  const CameraSensor &a = rec.cam[0], &b = rec.cam[1];
  if (a.width == b.width && a.height == b.height) return;
  throw recording_error_at(yaml[1], b.line.resolution,
                           "resolution [" + std::to_string(b.width) + ", " + std::to_string(b.height) + "] differs from " +
                               shown_path(yaml[0]) + ":" + std::to_string(a.line.resolution) + " resolution [" +
                               std::to_string(a.width) + ", " + std::to_string(a.height) +
                               "]: both cameras must have the same resolution");
}

// A folder that holds no recording: said as what it is (a sensor's folder,
// a camera's data folder) and where the recording would be, rather than
// "cam0/sensor.yaml does not exist" one level too deep.
void check_is_recording(const std::string& dir) {
  auto has = [&](const char* sub) { return path_present(dir + "/" + sub); };
  if (has("mav0") || has(layout::kCamDir[0]) || has(layout::kCamDir[1]) || has(layout::kImuDir)) return;
  const size_t slash = dir.find_last_of('/');
  const std::string parent = slash == std::string::npos ? "." : slash == 0 ? "/" : dir.substr(0, slash);
  const std::string hint = " (docs/recording-format.md): give the recording folder REC, or REC/mav0";
  if (has("sensor.yaml") || has("data.csv"))
    throw recording_error_in(dir, "is the folder of one sensor (it holds sensor.yaml or data.csv), not a "
                                              "recording" + hint + " (here " + shown_path(parent) + " or its parent)");
  throw recording_error_in(dir, "is not a recording folder: it holds no mav0/, cam0/, cam1/ or imu0/" + hint);
}

void count_gaps(Recording& rec) {
  GapReport& g = rec.gaps;
  for (size_t i = 1; i < rec.frames.size(); ++i) {
    const double dt = static_cast<double>(rec.frames[i].t_ns - rec.frames[i - 1].t_ns) * 1e-9;
    if (dt > 1.5 * rec.frame_period_s) {
      ++g.frame_gaps;
      g.frames_missing += std::max(1L, std::lround(dt / rec.frame_period_s) - 1);
      g.longest_frame_gap_s = std::max(g.longest_frame_gap_s, dt);
    }
  }
  for (size_t i = 1; i < rec.imu_samples.size(); ++i) {
    const double dt = static_cast<double>(rec.imu_samples[i].t_ns - rec.imu_samples[i - 1].t_ns) * 1e-9;
    if (dt > kGapPeriods * rec.imu_period_s) {
      ++g.gyro_holes;
      g.longest_gyro_hole_s = std::max(g.longest_gyro_hole_s, dt);
    }
  }
}

// Refuses a ground truth whose samples give V at none of the frames (in
// another time unit, of another recording): present, it would be read as
// "no frame has ground truth" (was: exit 0, no figures, the file unused).
void check_groundtruth_coverage(const Recording& rec, const std::string& gt_csv, const std::string& cam_csv) {
  std::vector<uint64_t> t;
  t.reserve(rec.frames.size());
  for (const FramePairEntry& f : rec.frames) t.push_back(f.t_ns);
  const std::vector<double> v = true_forward_velocity(rec.groundtruth, t);
  if (std::any_of(v.begin(), v.end(), [](double x) { return !std::isnan(x); })) return;
  throw recording_error_in(gt_csv, "the ground-truth samples (t = " + std::to_string(rec.groundtruth.front().t_ns) +
                                       " .. " + std::to_string(rec.groundtruth.back().t_ns) +
                                       " ns) cover none of the frames of " + shown_path(cam_csv) + " (t = " +
                                       std::to_string(t.front()) + " .. " + std::to_string(t.back()) +
                                       " ns): no frame can be compared (remove the file for a run without ground truth)");
}

}  // namespace

void set_periods(Recording& rec) {
  std::vector<uint64_t> t;
  t.reserve(rec.frames.size());
  for (const FramePairEntry& f : rec.frames) t.push_back(f.t_ns);
  rec.frame_period_s = rec.frames.size() >= 2 ? median_interval_s(t) : 1.0 / rec.cam[0].rate_hz;
  t.clear();
  for (const ImuSample& s : rec.imu_samples) t.push_back(s.t_ns);
  rec.imu_period_s = rec.imu_samples.size() >= 2 ? median_interval_s(t) : 1.0 / rec.imu.rate_hz;
}

// Counts the frames whose interval the gyro's span does not hold; refuses a
// gyro that covers none (stopped before the first frame, started after the
// last, or 1000 s away): no heading change could be measured at all.
void check_gyro_coverage(Recording& rec, const std::string& imu_csv, const std::string& cam_csv) {
  const uint64_t g0 = rec.imu_samples.front().t_ns, g1 = rec.imu_samples.back().t_ns;
  // The engines' tolerance: an interval end within the gyro gap of a sample is covered.
  const uint64_t tol = static_cast<uint64_t>(std::llround(gyro_gap_s(rec.imu_period_s) * 1e9));
  auto covers = [&](uint64_t from, uint64_t to) { return from + tol >= g0 && to <= g1 + tol; };
  const std::vector<FramePairEntry>& f = rec.frames;
  long covered = 0;
  for (size_t i = 1; i < f.size(); ++i) {
    if (covers(f[i - 1].t_ns, f[i].t_ns)) ++covered;
    else ++rec.gaps.frames_beyond_gyro;
  }
  const bool none = f.size() == 1 ? !covers(f[0].t_ns, f[0].t_ns) : covered == 0;
  if (none)
    throw recording_error_in(imu_csv, "the gyro samples (t = " + std::to_string(g0) + " .. " + std::to_string(g1) +
                                          " ns) cover none of the intervals between the frames of " + shown_path(cam_csv) +
                                          " (t = " + std::to_string(f.front().t_ns) + " .. " +
                                          std::to_string(f.back().t_ns) + " ns): no heading change can be measured");
}

Recording load_recording(const std::string& dir_arg) {
  Recording rec;
  std::string dir = dir_arg;
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();  // "rec/" -> "rec": clean paths in messages
  if (const std::string why = why_not_a_folder(dir, "recording folder"); !why.empty())
    throw recording_error_in(dir, why == "does not exist" ? "recording folder does not exist" : why);
  if (path_present(dir + "/mav0") && !is_dir(dir + "/mav0"))  // REC/mav0 is the data when it is there
    throw recording_error_in(dir + "/mav0", why_not_a_folder(dir + "/mav0"));
  check_is_recording(dir);
  rec.root = is_dir(dir + "/mav0") ? dir + "/mav0" : dir;
  const std::string& root = rec.root;
  std::string yaml[2];
  for (int c = 0; c < 2; ++c) {
    yaml[c] = root + "/" + layout::kCamDir[c] + "/sensor.yaml";
    rec.cam[c] = read_camera_yaml(yaml[c]);
  }
  check_same_resolution(rec, yaml);
  for (int c = 0; c < 2; ++c) check_lens_invertible(rec.cam[c], yaml[c]);
  rec.imu = read_imu_yaml(root + "/" + layout::kImuDir + "/sensor.yaml");

  FrameNames named;
  const CamRows c0 = read_cam_rows(root, 0, named);
  const CamRows c1 = read_cam_rows(root, 1, named);
  if (c0.rows.empty()) throw recording_error_at(c0.csv, 2, "no frames");
  rec.frames = pair_frames(c0, c1);

  const std::string imu_csv = root + "/" + layout::kImuDir + "/data.csv";
  rec.imu_samples = read_imu(imu_csv);
  if (rec.imu_samples.empty()) throw recording_error_at(imu_csv, 2, "no gyro samples");

  const std::string gt_csv = root + "/" + layout::kGroundTruthDir + "/data.csv";
  std::vector<long> gt_line;  // each sample's line
  if (path_present(gt_csv)) {  // absent: no ground truth; present, it must hold some
    rec.groundtruth = read_groundtruth(gt_csv, gt_line);
    if (rec.groundtruth.empty())
      throw recording_error_at(gt_csv, 2,
                               "no ground-truth samples after the header (remove the file for a run without ground "
                               "truth)");
  }

  for (int c = 0; c < 2; ++c) check_first_frame(rec.frames.front().path[c], c, rec.cam[c], yaml[c]);

  set_periods(rec);
  {
    std::vector<long> lines;  // pair_frames pairs cam0's rows one to one, in order
    lines.reserve(c0.rows.size());
    for (const CsvRow& r : c0.rows) lines.push_back(r.line);
    const FrameGlitches fg = skip_frame_glitches(rec.frames, lines, rec.frame_period_s);
    rec.frame_glitches = fg.count;
    if (fg.count > 0) {
      rec.frame_glitch_text = format_frame_glitches(fg, shown_path(c0.csv), rec.frame_period_s);
      set_periods(rec);
    }
  }
  count_gaps(rec);
  const GyroGlitches glitches = repair_gyro_glitches(rec.imu_samples, rec.imu_period_s);
  rec.gyro_glitches = glitches.count;
  if (glitches.count > 0) rec.gyro_glitch_text = format_gyro_glitches(glitches, shown_path(imu_csv));
  check_gyro_coverage(rec, imu_csv, c0.csv);
  if (!rec.groundtruth.empty()) {
    check_groundtruth_coverage(rec, gt_csv, c0.csv);  // first: times in another unit break the rate too
    // A velocity the positions contradict (zeros a tool wrote for one it did
    // not have: 'the true speed is 0 throughout', every figure against it,
    // exit 0) is refused.
    long at = 0;
    if (const std::string why = why_velocity_is_not_the_positions_rate(rec.groundtruth, gt_line, at); !why.empty())
      throw recording_error_at(gt_csv, at, why);
  }
  return rec;
}

std::string format_gaps(const GapReport& g) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%d frame gaps (about %ld pairs missing, longest %.3f s), %d gyro holes (longest %.3f s)",
                g.frame_gaps, g.frames_missing, g.longest_frame_gap_s, g.gyro_holes, g.longest_gyro_hole_s);
  std::string s = buf;
  if (g.frames_beyond_gyro > 0) s += ", " + std::to_string(g.frames_beyond_gyro) + " frames beyond the gyro's samples";
  return s;
}

bool has_gaps(const GapReport& g) { return g.frame_gaps > 0 || g.gyro_holes > 0 || g.frames_beyond_gyro > 0; }

double body_yaw_rate(const ImuSensor& imu, const ImuSample& s) {
  // Third row of R_BS times w_S.
  return imu.T_BS[8] * s.w[0] + imu.T_BS[9] * s.w[1] + imu.T_BS[10] * s.w[2];
}

bool overwrites_recording(const Recording& rec, const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // A link to nothing is written through: where it leads counts (written_path).
  const std::string at = written_path(path);
  if (at.empty()) return false;
  const fs::path out = at;
  const fs::path root = fs::weakly_canonical(rec.root, ec);
  if (!ec) {
    const fs::path rel = out.lexically_relative(root);  // empty: unrelated; "..": outside
    if (!rel.empty() && *rel.begin() != "..") return true;
  }
  for (const FramePairEntry& f : rec.frames)
    for (const std::string& frame : f.path) {
      // Frames named inside the folder are covered above (and cost no lookup).
      if (frame.rfind(rec.root, 0) == 0 && frame.find("..") == std::string::npos) continue;
      if (fs::weakly_canonical(frame, ec) == out && !ec) return true;
    }
  return false;
}

}  // namespace lumavel::host
