// Writer -> reader round trip, and reading files spelled exactly as EuRoC ships them.
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/recording.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;
using fixture::error_of;

TEST_GROUP(RecordingIo) {
  fixture::TempDir dir;
  std::string rec() { return dir.path() + "/rec"; }
};

TEST(RecordingIo, RoundTripKeepsEverything) {
  fixture::Options o;
  fixture::write_recording(rec(), o);
  const Recording r = load_recording(rec());
  STRCMP_EQUAL((rec() + "/mav0").c_str(), r.root.c_str());

  const CameraSensor want = fixture::left_camera(40, 30, 0.04);
  const CameraSensor& c1 = r.cam[1];
  DOUBLES_EQUAL(want.rate_hz, c1.rate_hz, 0);
  LONGS_EQUAL(40, c1.width);
  LONGS_EQUAL(30, c1.height);
  DOUBLES_EQUAL(want.fu, c1.fu, 0);
  DOUBLES_EQUAL(want.fv, c1.fv, 0);
  DOUBLES_EQUAL(want.cu, c1.cu, 0);
  DOUBLES_EQUAL(want.cv, c1.cv, 0);
  CHECK(want.distortion == c1.distortion);
  CHECK(want.T_BS == c1.T_BS);
  DOUBLES_EQUAL(-0.04, r.cam[0].T_BS[3], 0);
  DOUBLES_EQUAL(1.7e-4, r.imu.gyroscope_noise_density, 0);
  DOUBLES_EQUAL(-1, r.imu.gyroscope_random_walk, 0);  // absent

  LONGS_EQUAL(o.frames, r.frames.size());
  for (int i = 0; i < o.frames; ++i) {
    const FramePairEntry& f = r.frames[static_cast<size_t>(i)];
    CHECK_EQUAL(fixture::frame_time(o, i), f.t_ns);
    for (int c = 0; c < 2; ++c) {
      const GrayImage img = read_gray_image(f.path[c]);
      CHECK(img.px == fixture::frame_pixels(o, i, c));
    }
  }
  DOUBLES_EQUAL(0.01, r.frame_period_s, 1e-12);
  DOUBLES_EQUAL(0.002, r.imu_period_s, 1e-12);
  CHECK(r.imu_samples.size() > 60);
  CHECK_EQUAL(o.t0 - o.frame_dt, r.imu_samples.front().t_ns);
  DOUBLES_EQUAL(0.001, r.imu_samples[3].w[0], 0);
  DOUBLES_EQUAL(-0.002, r.imu_samples[3].w[1], 0);
  DOUBLES_EQUAL(o.yaw_rate, r.imu_samples[3].w[2], 0);
  DOUBLES_EQUAL(9.81, r.imu_samples[3].a[2], 0);
  CHECK(!r.groundtruth.empty());
  const GroundTruthSample& g = r.groundtruth[7];
  const double yaw = o.yaw_rate * static_cast<double>(g.t_ns - o.t0) * 1e-9;
  DOUBLES_EQUAL(std::cos(yaw / 2), g.q[0], 0);
  DOUBLES_EQUAL(std::sin(yaw / 2), g.q[3], 0);
  DOUBLES_EQUAL(o.speed * std::sin(yaw), g.v[1], 0);
  LONGS_EQUAL(0, r.gaps.frame_gaps);
  LONGS_EQUAL(0, r.gaps.gyro_holes);
}

TEST(RecordingIo, PgmFramesAndRecordingWithoutMav0Level) {
  fixture::Options o;
  o.format = ImageFormat::kPgm;
  o.groundtruth = false;
  fixture::write_recording(rec(), o);
  const Recording r = load_recording(rec() + "/mav0//");  // REC/mav0 given directly
  STRCMP_EQUAL((rec() + "/mav0").c_str(), r.root.c_str());
  CHECK(r.groundtruth.empty());
  CHECK(r.frames[0].path[0].size() > 4);
  STRCMP_EQUAL(".pgm", r.frames[0].path[0].substr(r.frames[0].path[0].size() - 4).c_str());
  CHECK(read_gray_image(r.frames[5].path[1]).px == fixture::frame_pixels(o, 5, 1));
}

TEST(RecordingIo, HeadersAreExactlyTheContracts) {
  fixture::write_recording(rec());
  const std::string m = rec() + "/mav0/";
  STRCMP_EQUAL("#timestamp [ns],filename", fixture::read_lines(m + "cam0/data.csv")[0].c_str());
  STRCMP_EQUAL("#timestamp [ns],filename", fixture::read_lines(m + "cam1/data.csv")[0].c_str());
  STRCMP_EQUAL(
      "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2],"
      "a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]",
      fixture::read_lines(m + "imu0/data.csv")[0].c_str());
  STRCMP_EQUAL(
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], q_RS_z [], "
      "v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], b_w_RS_S_x [rad s^-1], b_w_RS_S_y [rad s^-1], "
      "b_w_RS_S_z [rad s^-1], b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], b_a_RS_S_z [m s^-2]",
      fixture::read_lines(m + "state_groundtruth_estimate0/data.csv")[0].c_str());
  const std::string yaml = fixture::read_text(m + "cam0/sensor.yaml");
  for (const char* key : {"sensor_type: camera", "rate_hz: 100", "resolution: [40, 30]", "camera_model: pinhole",
                          "intrinsics: [36, 36, 19.5, 14.5]", "distortion_model: radial-tangential",
                          "distortion_coefficients: [0.01, -0.002, 0.0003, -0.0004]", "T_BS:", "cols: 4", "rows: 4",
                          "data: ["})
    STRCMP_CONTAINS(key, yaml.c_str());
  const std::string frame0 = fixture::read_lines(m + "cam0/data.csv")[1];
  STRCMP_EQUAL("1000000000,1000000000.png", frame0.c_str());
}

TEST(RecordingIo, ReadsEuRoCFilesVerbatim) {
  // cam0/sensor.yaml of EuRoC MH_01_easy, as distributed.
  fixture::write_recording(rec());
  const std::string yaml = rec() + "/mav0/cam0/sensor.yaml";
  fixture::write_text(yaml,
                      "# General sensor definitions.\n"
                      "sensor_type: camera\n"
                      "comment: VI-Sensor cam0 (MT9M034)\n"
                      "\n"
                      "# Sensor extrinsics wrt. the body-frame.\n"
                      "T_BS:\n"
                      "  cols: 4\n"
                      "  rows: 4\n"
                      "  data: [0.0148655429818, -0.999880929698, 0.00414029679422, -0.0216401454975,\n"
                      "         0.999557249008, 0.0149672133247, 0.025715529948, -0.064676986768,\n"
                      "        -0.0257744366974, 0.00375618835797, 0.999660727178, 0.00981073058949,\n"
                      "         0.0, 0.0, 0.0, 1.0]\n"
                      "\n"
                      "# Camera specific definitions.\n"
                      "rate_hz: 20\n"
                      "resolution: [752, 480]\n"
                      "camera_model: pinhole\n"
                      "intrinsics: [458.654, 457.296, 367.215, 248.375] #fu, fv, cu, cv\n"
                      "distortion_model: radial-tangential\n"
                      "distortion_coefficients: [-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05]\n");
  const CameraSensor c = read_camera_yaml(yaml);
  LONGS_EQUAL(752, c.width);
  LONGS_EQUAL(480, c.height);
  DOUBLES_EQUAL(367.215, c.cu, 0);
  DOUBLES_EQUAL(1.76187114e-05, c.distortion[3], 0);
  DOUBLES_EQUAL(-0.064676986768, c.T_BS[7], 0);
  DOUBLES_EQUAL(20, c.rate_hz, 0);
  STRCMP_EQUAL("VI-Sensor cam0 (MT9M034)", c.comment.c_str());
  // The EuRoC imu0 file, and a line of EuRoC imu data (no spaces, CRLF tolerated).
  const std::string imu_yaml = rec() + "/mav0/imu0/sensor.yaml";
  fixture::write_text(imu_yaml,
                      "#Default imu sensor yaml file\nsensor_type: imu\ncomment: VI-Sensor IMU (ADIS16448)\n\n"
                      "T_BS:\n  cols: 4\n  rows: 4\n  data: [1.0, 0.0, 0.0, 0.0,\n         0.0, 1.0, 0.0, 0.0,\n"
                      "         0.0, 0.0, 1.0, 0.0,\n         0.0, 0.0, 0.0, 1.0]\nrate_hz: 200\n\n"
                      "gyroscope_noise_density: 1.6968e-04     # [ rad / s / sqrt(Hz) ]   ( gyro \"white noise\" )\n"
                      "gyroscope_random_walk: 1.9393e-05       # [ rad / s^2 / sqrt(Hz) ] ( gyro bias diffusion )\n"
                      "accelerometer_noise_density: 2.0000e-3  # [ m / s^2 / sqrt(Hz) ]  ( accel \"white noise\" )\n"
                      "accelerometer_random_walk: 3.0000e-3    # [ m / s^3 / sqrt(Hz) ].  ( accel bias diffusion )\n");
  const ImuSensor imu = read_imu_yaml(imu_yaml);
  DOUBLES_EQUAL(200, imu.rate_hz, 0);
  DOUBLES_EQUAL(1.9393e-05, imu.gyroscope_random_walk, 0);
}

TEST(RecordingIo, ToleratesCrlfByteOrderMarkAndSpaces) {
  fixture::write_recording(rec());
  const std::string csv = rec() + "/mav0/imu0/data.csv";
  std::vector<std::string> lines = fixture::read_lines(csv);
  lines[0] = "\xEF\xBB\xBF" + lines[0] + "\r";
  lines[1] = lines[1].substr(0, lines[1].find(',')) + ", 0.5 , 0, 0.25,0,0,9.81\r";
  fixture::write_lines(csv, lines);
  const Recording r = load_recording(rec());
  DOUBLES_EQUAL(0.5, r.imu_samples[0].w[0], 0);
  DOUBLES_EQUAL(0.25, r.imu_samples[0].w[2], 0);
}

TEST(RecordingIo, WriterRefusesTimestampsOutOfOrder) {
  fixture::Options o;
  RecordingWriter w(rec(), fixture::left_camera(40, 30, -0.04), fixture::left_camera(40, 30, 0.04), ImuSensor{});
  const std::vector<uint8_t> px = fixture::frame_pixels(o, 0, 0);
  w.add_frame_pair(2000, px.data(), px.data());
  const std::string e = error_of([&] { w.add_frame_pair_written(2000); });
  STRCMP_CONTAINS("cam0/data.csv", e.c_str());
  STRCMP_CONTAINS("not after the previous one", e.c_str());
  const double z[3] = {0, 0, 0};
  w.add_imu(5, z, z);
  STRCMP_CONTAINS("imu0/data.csv", error_of([&] { w.add_imu(4, z, z); }).c_str());
}
