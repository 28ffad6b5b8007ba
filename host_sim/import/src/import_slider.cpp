#include "lumavel/host/import_slider.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "lumavel/host/cli.hpp"
#include "lumavel/host/groundtruth.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_writer.hpp"
#include "lumavel/host/rig.hpp"
#include "lumavel/host/rig_settings_check.hpp"
#include "lumavel/host/sensor_yaml.hpp"
#include "lumavel/host/slider_dataset.hpp"
#include "lumavel/host/time_shift_pairing.hpp"
#include "lumavel/units/config_fields.hpp"

namespace lumavel::host {
namespace {

// Camera upright and looking to the left of the travel: its x axis (image u)
// is body x (the slider's direction of travel), its y axis is body -z, its
// optical axis body +y. The dataset's camera orientation is identity, so the
// slider moves along the camera's +x.
Pose left_looking_pose(double x) { return {1, 0, 0, x, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1}; }

// Camera position (dataset world = camera axes) to body-frame world axes:
// (x, y, z) -> (x, z, -y), the rotation part of left_looking_pose.
void to_body_axes(const double p[3], double out[3]) {
  out[0] = p[0];
  out[1] = p[2];
  out[2] = -p[1];
}

double median_interval(const std::vector<SliderFrame>& f) {
  std::vector<double> dt;
  for (size_t i = 1; i < f.size(); ++i) dt.push_back(f[i].t - f[i - 1].t);
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

CameraSensor make_camera(const SliderCalib& c, int w, int h, double rate_hz, double x) {
  CameraSensor s;
  s.rate_hz = rate_hz;
  s.width = w;
  s.height = h;
  s.fu = c.fx;
  s.fv = c.fy;
  s.cu = c.cx;
  s.cv = c.cy;
  s.distortion = {c.k1, c.k2, c.p1, c.p2};
  s.T_BS = left_looking_pose(x);
  return s;
}

// Ground truth of the body origin (midpoint of the cameras, h/2 ahead of
// cam0), identity orientation, velocity by central differences over +-2
// samples (~40 ms at 100 Hz: the timestamps jitter by ~1 ms). A speed beyond
// the ground truth's bound (groundtruth.hpp; the real slider's are -0.16 to
// 0.34 m/s, with small backward steps) is refused naming gt_file's lines.
std::vector<GroundTruthSample> body_groundtruth(const std::vector<SliderPose>& poses, double h,
                                                const std::string& gt_file) {
  const size_t n = poses.size();
  std::vector<GroundTruthSample> out(n);
  for (size_t k = 0; k < n; ++k) {
    out[k].t_ns = slider_time_ns(poses[k].t);
    to_body_axes(poses[k].p, out[k].p);
    out[k].p[0] += 0.5 * h;
  }
  for (size_t k = 0; k < n; ++k) {
    const size_t a = k >= 2 ? k - 2 : 0, b = std::min(n - 1, k + 2);
    const double dt = poses[b].t - poses[a].t;
    for (int i = 0; i < 3; ++i) {
      out[k].v[i] = (out[b].p[i] - out[a].p[i]) / dt;
      if (const std::string why = why_implausible_speed(out[k].v[i]); !why.empty())
        throw recording_error_at(gt_file, poses[k].line,
                                 std::string("the speed along ") + "xyz"[i] + " from line " +
                                     std::to_string(poses[a].line) + " to line " + std::to_string(poses[b].line) +
                                     ": " + why);
    }
  }
  return out;
}

// The gyro's stamps: every imu period from the one at or before the first
// frame to the one after the last.
std::vector<uint64_t> imu_stamps(uint64_t t_first, uint64_t t_last, double rate_hz) {
  const uint64_t period = slider_time_ns(1.0 / rate_hz);
  std::vector<uint64_t> t;
  for (uint64_t s = t_first / period * period; s < t_last + period; s += period) t.push_back(s);
  return t;
}

// What `run` would refuse of the recording about to be written, by run's own
// checks (check_runnable_unwritten) on the values the sensor.yaml files and
// tables will hold, before anything is written (was: imported whole, then 'OUT/mav0 was written, but lumavel-sim
// run refuses it', the recording left behind). The check of the written
// recording, check_runnable, still follows.
void check_before_import(const std::string& data_dir, const std::string& out_rec, const CameraSensor& cam0,
                         const CameraSensor& cam1, const ImuSensor& imu, const std::vector<uint64_t>& frame_t,
                         const std::vector<GroundTruthSample>& truth) {
  Recording rec;
  rec.root = out_rec + "/mav0";
  rec.cam[0] = cam0;
  rec.cam[1] = cam1;
  rec.imu = imu;
  for (uint64_t t : frame_t) rec.frames.push_back({t, {}});
  for (uint64_t t : imu_stamps(frame_t.front(), frame_t.back(), imu.rate_hz)) rec.imu_samples.push_back({t, {}, {}});
  rec.groundtruth = truth;
  set_periods(rec);
  try {
    check_runnable_unwritten(rec);
  } catch (const RecordingError& e) {
    throw RecordingError(shown_path(data_dir) + ": the recording it makes is one lumavel-sim run refuses (nothing "
                         "written): " + e.what());
  }
}

// The slider must end further along +x than it starts: cam1 is cam0's frame
// h further on along +x. Said with the lines and the positions compared (was:
// 'the slider does not move along +x (the import assumes it does)', neither
// the lines nor the values said), as check_moves_along_x says its travel.
RecordingError not_along_plus_x(const std::vector<SliderPose>& poses, const std::string& gt_file) {
  const SliderPose &a = poses.front(), &b = poses.back();
  char m[400];
  std::snprintf(m, sizeof m,
                "from line %ld to line %ld the slider moves %.6g m along x (x %.6g m to %.6g m): the import makes cam1 "
                "from cam0's frames h further on along +x, which needs a slider that ends further along +x than it "
                "starts",
                a.line, b.line, b.p[0] - a.p[0], a.p[0], b.p[0]);
  return recording_error_in(gt_file, m);
}

// The tolerance of both checks below: the angle one pixel spans at fx.
double pixel_angle(double fx) { return std::atan(1.0 / fx); }

// The import reads positions as camera axes and makes cam1 from cam0's frames
// by time shift, with a zero gyro: a slider that does not turn. A pose turned
// by more than a pixel's angle at fx from the dataset's axes is refused (was:
// imported, exit 0, the turn written as none).
void check_does_not_turn(const std::vector<SliderPose>& poses, double fx, const std::string& gt_file) {
  const double limit = pixel_angle(fx);
  for (const SliderPose& p : poses) {
    const double n = std::sqrt(p.q[0] * p.q[0] + p.q[1] * p.q[1] + p.q[2] * p.q[2] + p.q[3] * p.q[3]);
    const double turn = 2 * std::acos(std::min(1.0, std::fabs(p.q[3]) / n));
    if (turn <= limit) continue;
    char b[512];
    std::snprintf(b, sizeof b,
                  "the camera is turned %.5g deg from the dataset's axes (qx qy qz qw = %g %g %g %g): the import takes "
                  "the positions as camera axes and makes cam1 from cam0's frames by time shift with a zero gyro, "
                  "which holds for a slider that does not turn: at most %.5g deg (a pixel at fx = %g px)",
                  turn * 180 / M_PI, p.q[0], p.q[1], p.q[2], p.q[3], limit * 180 / M_PI, fx);
    throw recording_error_at(gt_file, p.line, b);
  }
}

// The same of the travel: cam1 is cam0's frame h further on along x, which
// holds for a slider that moves along the camera's x axis. One whose travel,
// first pose to last, leaves that axis by more than a pixel's angle at fx is
// refused (was: a slider moving 1 m along y and 0.3 m along x, positions in
// another frame than the camera's, imported, exit 0, cam1 made by the x
// shift alone and the rig written with a baseline along x).
void check_moves_along_x(const std::vector<SliderPose>& poses, double fx, const std::string& gt_file) {
  const SliderPose &a = poses.front(), &b = poses.back();
  const double dx = b.p[0] - a.p[0], dy = b.p[1] - a.p[1], dz = b.p[2] - a.p[2];
  const double off = std::atan2(std::hypot(dy, dz), dx), limit = pixel_angle(fx);
  if (off <= limit) return;
  char m[512];
  std::snprintf(m, sizeof m,
                "from line %ld to line %ld the slider moves %.5g deg off the camera's x axis (x %.6g m, y %.6g m, z "
                "%.6g m): the import makes cam1 from cam0's frames h further on along x, which holds for a slider "
                "that moves along x: at most %.5g deg (a pixel at fx = %g px)",
                a.line, b.line, off * 180 / M_PI, dx, dy, dz, limit * 180 / M_PI, fx);
  throw recording_error_in(gt_file, m);
}

// Each frame's position is the ground truth's at the frame's time; a ground
// truth whose times miss every frame (another clock or time unit) gave no
// position at all, refused as 'no frame has a partner ... (baseline longer
// than the travel?)', a cause that was not the one.
void check_truth_spans_a_frame(const std::vector<double>& x, const SliderDataset& d, const std::string& gt_file) {
  if (std::any_of(x.begin(), x.end(), [](double v) { return !std::isnan(v); })) return;
  char b[400];
  std::snprintf(b, sizeof b,
                "its times (%.9g .. %.9g s, lines %ld..%ld) span none of the frames' times in images.txt (%.9g .. %.9g "
                "s): a frame's position is the ground truth's at its time (another clock or time unit?)",
                d.poses.front().t, d.poses.back().t, d.poses.front().line, d.poses.back().line, d.frames.front().t,
                d.frames.back().t);
  throw recording_error_in(gt_file, b);
}

// No frame has one h further on: said with the frames' own travel, so that
// a slider that barely moved is told from a baseline too long for its run.
RecordingError no_partner(const std::vector<double>& x, double baseline, const std::string& gt_file) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : x)
    if (!std::isnan(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  char b[320];
  std::snprintf(b, sizeof b,
                "no frame has a partner %.6g m further on: the frames span %.6g m of the slider's travel (x %.6g .. "
                "%.6g m), and the baseline (--baseline) must be shorter",
                baseline, hi - lo, lo, hi);
  return recording_error_in(gt_file, b);
}

}  // namespace

ImportSliderSummary import_slider(const std::string& data_dir, const std::string& out_rec,
                                  const ImportSliderOptions& options) {
  if (!(options.baseline > 0) || !std::isfinite(options.baseline))
    throw std::invalid_argument("the baseline must be a positive number of metres");
  // '-' made a folder named '-' (a recording is a folder: it cannot go to
  // standard output), refused as render refuses it.
  if (out_rec == "-") throw std::runtime_error("- (OUT_REC): " + why_dash_is_not_an_output("recording", "folder"));
  const SliderDataset d = read_slider_dataset(data_dir);
  const std::string gt_file = data_dir + "/groundtruth.txt";
  if (!(d.poses.back().p[0] > d.poses.front().p[0])) throw not_along_plus_x(d.poses, gt_file);
  check_does_not_turn(d.poses, d.calib.fx, gt_file);
  check_moves_along_x(d.poses, d.calib.fx, gt_file);
  // Before anything is written: its speeds are checked.
  const std::vector<GroundTruthSample> truth = body_groundtruth(d.poses, options.baseline, gt_file);
  if (d.calib.k3 != 0)
    std::fprintf(stderr, "import-slider: warning: %s: k3 = %g dropped (the recording format has k1 k2 p1 p2)\n",
                 shown_path(data_dir + "/calib.txt").c_str(), d.calib.k3);

  ImportSliderSummary sum;
  sum.frames_in = d.frames.size();
  std::vector<double> x(d.frames.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = slider_position_at(d.poses, d.frames[i].t);
  check_truth_spans_a_frame(x, d, gt_file);
  const std::vector<ShiftedPair> pairs = plan_time_shift_pairs(x, options.baseline);
  if (pairs.empty()) throw no_partner(x, options.baseline, gt_file);

  std::vector<GrayImage> img(d.frames.size());
  const std::string images_txt = data_dir + "/images.txt";
  auto image = [&](size_t i) -> const GrayImage& {
    if (img[i].px.empty()) {
      const SliderFrame& f = d.frames[i];
      try {
        img[i] = read_gray_image(f.path);
      } catch (const RecordingError& e) {
        throw recording_error_at(images_txt, f.line, e.what());  // the row that names the image
      }
      const size_t first_i = pairs.front().cam0;
      const GrayImage& first = img[first_i].px.empty() ? img[i] : img[first_i];
      auto size = [](const GrayImage& g) { return std::to_string(g.width) + "x" + std::to_string(g.height); };
      if (img[i].width != first.width || img[i].height != first.height)
        throw recording_error_at(images_txt, f.line,
                                 shown_path(f.path) + " is " + size(img[i]) + ", but " + shown_path(d.frames[first_i].path) + " (line " +
                                     std::to_string(d.frames[first_i].line) + ") is " + size(first) +
                                     ": every frame must have the same size");
    }
    return img[i];
  };
  const GrayImage& ref = image(pairs.front().cam0);
  const int w = ref.width, hgt = ref.height;
  const double h = options.baseline;
  const double rate = 1.0 / median_interval(d.frames);
  ImuSensor imu;
  imu.rate_hz = options.imu_rate_hz;
  imu.comment = "synthesised by lumavel-sim import-slider: the slider does not turn, the gyro reads zero";
  CameraSensor cam0 = make_camera(d.calib, w, hgt, rate, -0.5 * h);
  CameraSensor cam1 = make_camera(d.calib, w, hgt, rate, 0.5 * h);
  // What `run` would refuse in the recording is refused here, naming calib.txt.
  check_intrinsics(cam0, data_dir + "/calib.txt", 1);
  check_lens_invertible(cam0, data_dir + "/calib.txt");
  cam0.comment = "slider camera (Event-Camera Dataset), imported by lumavel-sim import-slider";
  cam1.comment = "cam0's frames time-shifted to the slider position x + " + std::to_string(h) +
                 " m (pixelwise blend of the two bracketing frames, weighted by position)";
  std::vector<uint64_t> frame_t;
  for (const ShiftedPair& p : pairs) frame_t.push_back(slider_time_ns(d.frames[p.cam0].t));
  check_before_import(data_dir, out_rec, cam0, cam1, imu, frame_t, truth);
  // Written over, an earlier recording kept its frames beside the new ones in
  // cam0/data and cam1/data and was lost without a word: refused, as render
  // refuses it, unless --force (then it is replaced whole).
  const std::string mav0 = out_rec + "/mav0";
  bool made_here = !path_present(mav0);
  std::error_code not_a_folder;
  if (!made_here && std::filesystem::is_directory(out_rec, not_a_folder)) {
    if (!options.force) throw recording_error_in(mav0, "already exists (use --force to replace it)");
    // Nor may --force delete what it is about to read: the images are read
    // while the recording is written, after the old one is gone.
    if (lies_inside(data_dir, mav0))
      throw recording_error_in(data_dir, "lies inside " + shown_path(mav0) +
                                                         ", which --force would delete before reading it: write the "
                                                         "recording to another folder");
    std::filesystem::remove_all(mav0);
    made_here = true;
  }
  // A frame found damaged while writing (the images are read lazily) left the
  // pairs before it as a recording, and 'run' on it then blamed the gyro file
  // this import had not finished ("imu0/data.csv:2: no gyro samples"). A
  // mav0 this import made is removed on any failure (one under OUT_REC when
  // that is not a folder is the writer's to refuse, not this import's to delete).
  const auto write = [&] {
    RecordingWriter out(out_rec, cam0, cam1, imu);

    std::vector<uint8_t> shifted(ref.px.size());
    for (const ShiftedPair& p : pairs) {
      const GrayImage& a = image(p.before);
      const GrayImage& b = image(p.before + 1);
      blend_gray(a.px.data(), b.px.data(), p.w, shifted.size(), shifted.data());
      out.add_frame_pair(slider_time_ns(d.frames[p.cam0].t), image(p.cam0).px.data(), shifted.data());
      sum.max_blend_gap_m = std::max(sum.max_blend_gap_m, x[p.before + 1] - x[p.before]);
    }
    sum.pairs = pairs.size();

    // Zero gyro (and gravity only) at imu_rate_hz, covering every frame.
    const double zero[3] = {0, 0, 0}, gravity[3] = {0, 0, 9.81};
    for (uint64_t t : imu_stamps(frame_t.front(), frame_t.back(), options.imu_rate_hz)) {
      out.add_imu(t, zero, gravity);
      ++sum.imu_samples;
    }

    for (const GroundTruthSample& g : truth) {
      out.add_groundtruth(g);
      ++sum.groundtruth_samples;
    }
    out.finish();
  };
  try {
    write();
  } catch (...) {
    std::error_code ignored;
    if (made_here) std::filesystem::remove_all(mav0, ignored);
    throw;
  }
  // As render's: a focal length of 1e300 px in calib.txt (of which only the
  // ratios are checked above) was written, exit 0, and run refused it.
  check_runnable(out_rec);
  return sum;
}

void add_import_slider_command(cli::Tool& tool) {
  struct Args {
    std::string data, out;
    ImportSliderOptions o;
  };
  auto a = std::make_shared<Args>();
  CLI::App* c = tool.command(
      "import-slider",
      "turn a single-camera slider sequence into a two-camera recording\n\n"
      "Turns a single-camera slider sequence of the Event-Camera Dataset (images.txt,\n"
      "groundtruth.txt, calib.txt; e.g. slider_depth) into a two-camera recording\n"
      "(docs/recording-format.md): cam1 at time t is the image cam0 took where the\n"
      "slider was h further on, a pixelwise blend of the two frames bracketing\n"
      "x(t) + h, weighted by position. Valid for a pure translation past a static\n"
      "scene; the gyro reads zero.",
      [a] {
        const ImportSliderSummary s = import_slider(a->data, a->out, a->o);
        std::printf("import-slider: %zu of %zu frames paired at h = %g m (largest blended frame spacing %.4f m), "
                    "%zu gyro samples, %zu ground-truth samples -> %s\n",
                    s.pairs, s.frames_in, a->o.baseline, s.max_blend_gap_m, s.imu_samples, s.groundtruth_samples,
                    shown_path(a->out).c_str());
        return 0;
      });
  c->add_option("DATA_DIR", a->data, "the dataset folder (images.txt, groundtruth.txt, calib.txt)")
      ->required()
      ->type_name("")->check(cli::path_name());
  c->add_option("OUT_REC", a->out, "the recording folder to write")->required()->type_name("")->check(cli::recording_out());
  // The baseline's range is the configuration's, which run holds a recording
  // to (was: (0, 1], and 0.5 mm imported, then refused by run's check).
  const config::FieldSpec& h = config::spec(config::Quantity::kBaseline);
  char baseline_help[128];
  std::snprintf(baseline_help, sizeof baseline_help, "h in metres, cam1 ahead of cam0, %s..%s (default %g)",
                cli::number_text(h.lo).c_str(), cli::number_text(h.hi).c_str(), kDefaultSliderBaseline);
  c->add_option("--baseline", a->o.baseline, baseline_help)->type_name("H")->check(cli::number_in(h.lo, h.hi));
  c->add_flag("--force", a->o.force, "replace an existing OUT_REC/mav0");
}

int import_slider_main(int argc, char** argv) {
  return cli::run_command_alone("lumavel-sim", add_import_slider_command, argc, argv);
}

}  // namespace lumavel::host
