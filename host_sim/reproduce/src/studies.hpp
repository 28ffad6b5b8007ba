// The studies `reproduce` runs: which scenario, rendered how, run at which
// working resolutions, compared with which figure of the paper.
#pragma once
#include <string>
#include <vector>

namespace lumavel::host::reproduce {

struct WorkSize {
  int width, height;
};

struct Case {
  std::string id;         // folder and plot name
  std::string scenario;   // file under the scenarios folder
  int render_w = -1, render_h = -1;  // -1: the scenario's resolution
  double exposure = -1;   // -1: the scenario's
  double duration = -1;   // -1: the scenario's
  std::vector<WorkSize> work;        // working resolutions to run at
  std::string label;      // row label in the results
  double paper_value = -1;  // the paper's figure for this row (-1: none)
  std::string camera_mismatch;  // a photometric preset applied to both cameras ("": the scenario's)
};

struct Study {
  std::string title;
  std::string what;       // one paragraph: what is compared and how
  std::string metric;     // "E", "worst", "L1", "flags", "lens", "gyro"
  std::vector<Case> cases;
};

std::vector<Study> paper_studies(bool quick);

// Rigs as users build them: near clutter, a street, reversals, each also
// with two cameras that are not photometric twins; a wall seen by matched
// and by mismatched cameras.
Study real_rig_study(bool quick);

// Lens distortion: undistorted vs corrected vs ignored (study_lens.cpp).
Study lens_study(bool quick);

// How a case of the lens study is rendered and run: with the scenario's lens
// removed, as if the lens were pinhole (run --ignore-distortion), corrected
// by column tables only (run --lens-columns), and the folder of the render it
// shares. Other cases: all false, render_id the case id.
struct LensVariant {
  bool no_lens = false, ignore_distortion = false, by_columns = false;
  std::string render_id;
};
LensVariant lens_variant(const Case& c);

// Gyro zero-rate offset: learned vs not, with and without an offset
// (study_gyro_offset.cpp).
Study gyro_offset_study(bool quick);

// How a case of the gyro offset study is rendered and run: with the
// scenario's gyro offset removed, with offset learning (off: run
// --no-gyro-offset-learning), and the folder of the render it shares. Other
// cases: no_offset false, learning true, render_id lens_variant's.
struct GyroVariant {
  bool no_offset = false, learning = true;
  std::string render_id;
};
GyroVariant gyro_variant(const Case& c);

}  // namespace lumavel::host::reproduce
