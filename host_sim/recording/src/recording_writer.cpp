#include "lumavel/host/recording_writer.hpp"

#include <filesystem>

#include "lumavel/host/csv_table.hpp"
#include "lumavel/host/image_io.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/recording_layout.hpp"

namespace lumavel::host {
namespace {

std::string header(const std::vector<std::string>& columns, const char* sep) {
  std::string h = "#timestamp [ns]";
  for (const std::string& c : columns) h += sep + c;
  return h;
}

void make_dirs(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw recording_error_in(dir, "cannot create folder: " + ec.message());
}

}  // namespace

RecordingWriter::RecordingWriter(const std::string& rec_dir, const CameraSensor& cam0, const CameraSensor& cam1,
                                 const ImuSensor& imu, ImageFormat format)
    : root_(rec_dir + "/mav0"), cam_{cam0, cam1}, format_(format) {
  // A new folder is made; an existing one must be a folder (import-slider
  // onto a file said 'OUT/mav0/cam0/data: cannot create folder: Not a directory'),
  // and a new one must have a folder to be made in (render under a dangling
  // link said 'lnk/sub/mav0/cam0/data: cannot create folder: File exists').
  if (const std::string why = why_not_a_writable_folder(rec_dir, "folder to write the recording in"); !why.empty())
    throw recording_error_in(rec_dir, why);
  for (int c = 0; c < 2; ++c) {
    const std::string dir = root_ + "/" + layout::kCamDir[c];
    make_dirs(dir + "/data");
    write_camera_yaml(dir + "/sensor.yaml", cam_[c]);
    open_stream(cam_csv_[c], dir, header(layout::cam_columns(), ","));
  }
  const std::string imu_dir = root_ + "/" + layout::kImuDir;
  make_dirs(imu_dir);
  write_imu_yaml(imu_dir + "/sensor.yaml", imu);
  open_stream(imu_csv_, imu_dir, header(layout::imu_columns(), ","));
}

RecordingWriter::~RecordingWriter() {
  if (finished_) return;
  try {
    finish();
  } catch (...) {
    // Destructors must not throw; callers who care call finish().
  }
}

void RecordingWriter::open_stream(Stream& s, const std::string& dir, const std::string& head) {
  s.path = dir + "/data.csv";
  s.out = std::make_unique<OutputFile>(s.path, "the table");
  s.out->write(head + '\n');
}

void RecordingWriter::check_order(Stream& s, uint64_t t_ns) {
  if (finished_) throw recording_error_in(s.path, "row added after finish()");
  if (s.any && t_ns <= s.last_t)
    throw recording_error_in(s.path, "timestamp " + std::to_string(t_ns) + " is not after the previous one (" +
                                         std::to_string(s.last_t) + ")");
  s.any = true;
  s.last_t = t_ns;
}

std::string RecordingWriter::image_path(int cam, uint64_t t_ns) const {
  return root_ + "/" + layout::kCamDir[cam] + "/data/" + std::to_string(t_ns) +
         (format_ == ImageFormat::kPng ? ".png" : ".pgm");
}

void RecordingWriter::add_frame_pair(uint64_t t_ns, const uint8_t* cam0_px, const uint8_t* cam1_px) {
  const uint8_t* px[2] = {cam0_px, cam1_px};
  for (int c = 0; c < 2; ++c) {
    if (format_ == ImageFormat::kPng)
      write_png_gray(image_path(c, t_ns), px[c], cam_[c].width, cam_[c].height);
    else
      write_pgm(image_path(c, t_ns), px[c], cam_[c].width, cam_[c].height);
  }
  add_frame_pair_written(t_ns);
}

void RecordingWriter::add_frame_pair_written(uint64_t t_ns) {
  for (int c = 0; c < 2; ++c) {
    check_order(cam_csv_[c], t_ns);
    const std::string name = std::to_string(t_ns) + (format_ == ImageFormat::kPng ? ".png" : ".pgm");
    cam_csv_[c].out->write(std::to_string(t_ns) + ',' + name + '\n');
  }
}

void RecordingWriter::add_imu(uint64_t t_ns, const double w[3], const double a[3]) {
  check_order(imu_csv_, t_ns);
  std::string row = std::to_string(t_ns);
  for (int k = 0; k < 3; ++k) row += "," + format_double(w[k]);
  for (int k = 0; k < 3; ++k) row += "," + format_double(a[k]);
  imu_csv_.out->write(row + '\n');
}

void RecordingWriter::add_groundtruth(const GroundTruthSample& g) {
  if (!gt_csv_.out) {
    const std::string dir = root_ + "/" + layout::kGroundTruthDir;
    make_dirs(dir);
    // EuRoC spells this header "#timestamp, p_RS_R_x [m], ..." (comma-space).
    std::string head = "#timestamp";
    for (const std::string& c : layout::groundtruth_columns()) head += ", " + c;
    open_stream(gt_csv_, dir, head);
  }
  check_order(gt_csv_, g.t_ns);
  std::string row = std::to_string(g.t_ns);
  const double* groups[5] = {g.p, g.q, g.v, g.bw, g.ba};
  const int sizes[5] = {3, 4, 3, 3, 3};
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < sizes[k]; ++i) row += "," + format_double(groups[k][i]);
  gt_csv_.out->write(row + '\n');
}

void RecordingWriter::finish() {
  if (finished_) return;
  finished_ = true;
  Stream* streams[4] = {&cam_csv_[0], &cam_csv_[1], &imu_csv_, &gt_csv_};
  for (Stream* s : streams) {
    if (s->out) s->out->commit();
  }
}

}  // namespace lumavel::host
