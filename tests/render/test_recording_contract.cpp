// The files written follow the recording format (docs/recording-format.md): layout,
// exact headers, T_BS layout, timestamps, dropped and dark frames; the
// recording library's validating reader accepts them; shipped scenarios load.
#include <CppUTest/TestHarness.h>
// after TestHarness.h, which it needs
#include <CppUTest/MemoryLeakWarningPlugin.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/recording.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/stereo_rig.hpp"
#include "lumavel/host/render_command.hpp"
#include "render_test_support.hpp"

using namespace lumavel::host;
using namespace lumavel::host::render;
using namespace lumavel::host::render::test;

namespace {

Scenario small_recording() {
  Scenario s = empty_scenario(40, 30, 0.8);
  s.duration_s = 0.5;  // 30 frames at 60 Hz
  s.camera.misalignment_deg = 1.2;
  s.camera.exposure_frames = 0.5;
  s.dropped_frames = {3, 4, 17};
  s.lighting.dark.push_back({0.2, 0.25});
  s.imu.offset_s = 0.0017;
  s.imu.gyro_bias_z = 0.002;
  s.planes.push_back(wall_at(2.0, -5, 5, -3, 3, checker(0.2, 30, 220)));
  return s;
}

int run_render(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return render_main(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

// The recording library keeps function-local statics (csv column lists) that
// CppUTest's per-test leak check would report; leaks are checked by the
// AddressSanitizer build instead.
TEST_GROUP(RecordingContract) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(RecordingContract, HeadersAreExactlyTheContractOnes) {
  const std::string dir = temp_dir("contract_headers");
  render_recording(small_recording(), dir, RenderOptions{1, false});
  const std::string m = dir + "/mav0/";
  STRCMP_EQUAL("#timestamp [ns],filename", first_line(m + "cam0/data.csv").c_str());
  STRCMP_EQUAL("#timestamp [ns],filename", first_line(m + "cam1/data.csv").c_str());
  STRCMP_EQUAL(
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
      "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]",
      first_line(m + "imu0/data.csv").c_str());
  const std::string gt = first_line(m + "state_groundtruth_estimate0/data.csv");
  STRCMP_CONTAINS("p_RS_R_x [m]", gt.c_str());
  STRCMP_CONTAINS("q_RS_w []", gt.c_str());
  STRCMP_CONTAINS("v_RS_R_x [m s^-1]", gt.c_str());
  STRCMP_CONTAINS("b_a_RS_S_z [m s^-2]", gt.c_str());
  CHECK(gt.rfind("#timestamp", 0) == 0);
  // sensor.yaml keys and the T_BS layout.
  const std::string cam = read_text(m + "cam1/sensor.yaml");
  for (const char* key : {"sensor_type: camera", "rate_hz:", "resolution: [40, 30]", "camera_model: pinhole",
                          "intrinsics:", "distortion_model: radial-tangential", "distortion_coefficients:",
                          "T_BS:", "cols: 4", "rows: 4", "data:"})
    STRCMP_CONTAINS(key, cam.c_str());
  const std::string imu = read_text(m + "imu0/sensor.yaml");
  STRCMP_CONTAINS("sensor_type: imu", imu.c_str());
}

TEST(RecordingContract, ReaderAcceptsItAndGeometryRoundTrips) {
  const Scenario s = small_recording();
  const std::string dir = temp_dir("contract_reader");
  const RenderSummary sum = render_recording(s, dir, RenderOptions{2, false});
  CHECK_EQUAL(30, sum.frames);
  CHECK_EQUAL(3, sum.dropped);
  const Recording rec = load_recording(dir);
  CHECK_EQUAL(27u, rec.frames.size());
  CHECK_EQUAL(3L, rec.gaps.frames_missing);
  // Frame i at mid-exposure i / rate after start_ns; dropped ones absent.
  std::set<uint64_t> stamps;
  for (const auto& f : rec.frames) stamps.insert(f.t_ns);
  CHECK(stamps.count(1000000000u) == 1);
  CHECK(stamps.count(1000000000u + 2 * 16666667u) == 1);
  CHECK(stamps.count(1000000000u + 3 * 16666667u) == 0);
  CHECK(stamps.count(1000000000u + 17 * 16666667u) == 0);
  // T_BS and intrinsics as the rig has them.
  const StereoRig rig(s.camera);
  for (int c = 0; c < 2; ++c) {
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) DOUBLES_EQUAL(rig.T_BS(c).R(r, k), rec.cam[c].T_BS[static_cast<size_t>(4 * r + k)], 1e-12);
      DOUBLES_EQUAL(rig.T_BS(c).t[r], rec.cam[c].T_BS[static_cast<size_t>(4 * r + 3)], 1e-12);
    }
    DOUBLES_EQUAL(rig.pinhole().fu, rec.cam[c].fu, 1e-9);
    DOUBLES_EQUAL(19.5, rec.cam[c].cu, 0);
    DOUBLES_EQUAL(0.5 / 60, rec.cam[c].exposure_s, 1e-12);
  }
  // Gyro at its own rate, not on frame times; bias in w_z and in ground truth.
  CHECK_EQUAL(1000000000u + 1700000u, rec.imu_samples[0].t_ns);
  for (const auto& m : rec.imu_samples) CHECK(stamps.count(m.t_ns) == 0);
  DOUBLES_EQUAL(0.002, rec.imu_samples[10].w[2], 1e-12);  // straight line: only the bias
  CHECK(!rec.groundtruth.empty());
  DOUBLES_EQUAL(0.002, rec.groundtruth[0].bw[2], 0);
  // Images: 8-bit gray of the right size; frames in the dark interval are black.
  int dark = 0;
  for (const auto& f : rec.frames) {
    const GrayImage img = read_gray_image(f.path[0]);
    CHECK_EQUAL(40, img.width);
    CHECK_EQUAL(30, img.height);
    const double t = static_cast<double>(f.t_ns - 1000000000u) * 1e-9;
    const bool all_black = std::all_of(img.px.begin(), img.px.end(), [](uint8_t v) { return v == 0; });
    // Exposure 0.5 frame (8.3 ms): fully dark when [t - 4.2 ms, t + 4.2 ms] is inside [0.2, 0.25).
    if (t - 0.0042 >= 0.2 && t + 0.0042 < 0.25) {
      CHECK(all_black);
      ++dark;
    } else {
      CHECK(!all_black);
    }
  }
  CHECK(dark >= 2);
}

TEST(RecordingContract, CommandLine) {
  CHECK_EQUAL(0, run_render({"render", "--help"}));
  CHECK_EQUAL(2, run_render({"render"}));
  CHECK_EQUAL(2, run_render({"render", "a.yaml", "out", "--bogus"}));
  CHECK_EQUAL(2, run_render({"render", "a.yaml", "out", "--resolution", "40by30"}));
  CHECK_EQUAL(2, run_render({"render", "a.yaml", "out", "--camera-mismatch", "twins"}));
  CHECK_EQUAL(2, run_render({"render", "a.yaml", "out", "--camera-mismatch"}));
  CHECK_EQUAL(1, run_render({"render", "/nonexistent/a.yaml", temp_dir("cli_missing")}));
  // A real scenario, shortened and shrunk through the overrides.
  const std::string out = temp_dir("cli_render");
  const std::string scen = std::string(LUMAVEL_SCENARIO_DIR) + "/paper_sim_aligned.yaml";
  CHECK_EQUAL(0, run_render({"render", scen, out, "--resolution", "20x15", "--duration", "0.1", "--quiet"}));
  const Recording rec = load_recording(out);
  CHECK_EQUAL(20, rec.cam[0].width);
  CHECK_EQUAL(6u, rec.frames.size());
  // An existing recording is not overwritten without --force.
  CHECK_EQUAL(1, run_render({"render", scen, out, "--resolution", "20x15", "--duration", "0.1", "--quiet"}));
  CHECK_EQUAL(0, run_render({"render", scen, out, "--resolution", "20x15", "--duration", "0.1", "--quiet", "--force"}));
  // A photometric preset reaches the images and sensor.yaml's comment.
  const std::string mm = temp_dir("cli_mismatch");
  CHECK_EQUAL(0, run_render({"render", scen, mm, "--resolution", "20x15", "--duration", "0.1", "--quiet",
                             "--camera-mismatch", "cheap_pair"}));
  STRCMP_CONTAINS("photometric (cheap_pair): gain 1.2", read_text(mm + "/mav0/cam1/sensor.yaml").c_str());
  CHECK(read_text(out + "/mav0/cam1/sensor.yaml").find("photometric") == std::string::npos);
  CHECK(read_text(mm + "/mav0/cam1/data/1000000000.png") != read_text(out + "/mav0/cam1/data/1000000000.png"));
}

TEST(RecordingContract, ShippedScenariosLoad) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(LUMAVEL_SCENARIO_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    const Scenario s = load_scenario(e.path().string());  // throws with file:line on any problem
    CHECK(s.duration_s > 0);
    CHECK(!s.planes.empty());
    ++n;
  }
  CHECK(n >= 7);
}
