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
};

struct Study {
  std::string title;
  std::string what;       // one paragraph: what is compared and how
  std::string metric;     // "E", "worst", "L1", "flags"
  std::vector<Case> cases;
};

std::vector<Study> paper_studies(bool quick);

}  // namespace lumavel::host::reproduce
