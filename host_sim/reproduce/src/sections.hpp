// Sections of the results page that are not "render, run, tabulate E":
// the misalignment self-calibration and the real recording. Each returns its
// Markdown (a "## " section) and the issue targets it checked.
#pragma once
#include <string>
#include <vector>

namespace lumavel::host::reproduce {

struct SectionContext {
  std::string out;          // recordings cache (OUT of reproduce)
  std::string scenarios;    // scenario folder
  std::string slider_data;  // slider_depth folder (may be missing)
  int threads = 2;
  bool quick = false;
};

struct SectionTarget {
  std::string what, target, measured;
  bool met = false;
};

struct Section {
  std::string title;  // matched by --only
  std::string markdown;
  std::vector<SectionTarget> targets;
};

// Section titles, for --only before running them.
extern const char* const kCalibrationTitle;
extern const char* const kRealRecordingTitle;

Section calibration_section(const SectionContext& ctx);
Section real_recording_section(const SectionContext& ctx);

}  // namespace lumavel::host::reproduce
