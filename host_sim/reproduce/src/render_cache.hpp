// Renders kept between reproduce runs: a render is redone only when its
// scenario file or the way it is rendered changed.
#pragma once
#include <functional>
#include <string>

#include "lumavel/host/render/scenario.hpp"

namespace lumavel::host::reproduce {

struct CachedRender {
  bool reused = false;         // the folder already held this render
  bool from_earlier_run = false;  // ... and not from a render of this process
  int frames = 0;        // frame pairs rendered (0 when reused)
  double seconds = 0;    // time spent rendering (0 when reused)
};

// Loads `scenario_path`, applies `tweak` and renders it into `dir`, unless
// `dir` holds a render stamped with the same scenario file (path and
// modification time) and `key`, which must name everything `tweak` does.
CachedRender render_cached(const std::string& scenario_path, const std::string& dir, const std::string& key,
                           const std::function<void(render::Scenario&)>& tweak, int threads);

// Whether render_cached would reuse `dir` (for time estimates).
bool render_is_cached(const std::string& scenario_path, const std::string& dir, const std::string& key);

// What render_cached did in this process, for the page's header.
struct RenderTally {
  int rendered = 0;
  double seconds = 0;
  int reused_from_earlier_run = 0;
};
RenderTally render_tally();

}  // namespace lumavel::host::reproduce
