// Writes a recording in the EuRoC/ASL layout: REC/mav0/{cam0,cam1,imu0,
// state_groundtruth_estimate0}/ with the exact headers of the contract.
// Rows are appended as they come; timestamps must increase per stream.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "lumavel/host/output_file.hpp"
#include "lumavel/host/recording.hpp"

namespace lumavel::host {

enum class ImageFormat { kPng, kPgm };

class RecordingWriter {
 public:
  // Creates REC/mav0/... and the three sensor.yaml files. Frames must be
  // cam[c].width x cam[c].height.
  RecordingWriter(const std::string& rec_dir, const CameraSensor& cam0, const CameraSensor& cam1,
                  const ImuSensor& imu, ImageFormat format = ImageFormat::kPng);
  ~RecordingWriter();  // finishes if finish() was not called (errors then ignored)
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // Writes both images and their data.csv rows.
  void add_frame_pair(uint64_t t_ns, const uint8_t* cam0_px, const uint8_t* cam1_px);
  // For callers that write the images themselves (e.g. in parallel): the
  // file the row of add_frame_pair_written() will point at...
  std::string image_path(int cam, uint64_t t_ns) const;
  // ...and the rows for a pair already written there.
  void add_frame_pair_written(uint64_t t_ns);

  void add_imu(uint64_t t_ns, const double w_rad_s[3], const double a_m_s2[3]);
  void add_groundtruth(const GroundTruthSample& g);  // creates the folder on first use

  // Flushes and closes every data.csv (each written under a temporary name
  // and moved into place here); throws std::runtime_error "FILE: write
  // error: REASON" on a write error (OutputFile), as add_* may.
  void finish();

  const std::string& root() const { return root_; }  // REC/mav0

 private:
  struct Stream {
    std::string path;
    std::unique_ptr<OutputFile> out;
    uint64_t last_t = 0;
    bool any = false;
  };
  void open_stream(Stream& s, const std::string& dir, const std::string& header);
  void check_order(Stream& s, uint64_t t_ns);

  std::string root_;
  CameraSensor cam_[2];
  ImageFormat format_;
  Stream cam_csv_[2];
  Stream imu_csv_;
  Stream gt_csv_;
  bool finished_ = false;
};

}  // namespace lumavel::host
