#include "render_cache.hpp"

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

#include "lumavel/host/output_file.hpp"
#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host::reproduce {
namespace fs = std::filesystem;
namespace {

std::string stamp_of(const std::string& scenario_path, const std::string& key) {
  std::ostringstream stamp;
  stamp << scenario_path << " " << fs::last_write_time(scenario_path).time_since_epoch().count() << " " << key
        << "\n";
  return stamp.str();
}

std::string stamp_path(const std::string& dir) { return dir + "/.render-stamp"; }

bool holds(const std::string& dir, const std::string& stamp) {
  std::ifstream in(stamp_path(dir));
  std::stringstream have;
  have << in.rdbuf();
  return in && have.str() == stamp;
}

// Renders of this process: a folder rendered earlier in this run and used
// again is not "from an earlier run".
std::mutex g_mu;
std::set<std::string> g_rendered_here;
RenderTally g_tally;

}  // namespace

bool render_is_cached(const std::string& scenario_path, const std::string& dir, const std::string& key) {
  return holds(dir, stamp_of(scenario_path, key));
}

CachedRender render_cached(const std::string& scenario_path, const std::string& dir, const std::string& key,
                           const std::function<void(render::Scenario&)>& tweak, int threads) {
  const std::string stamp = stamp_of(scenario_path, key);
  if (holds(dir, stamp)) {
    std::lock_guard<std::mutex> lock(g_mu);
    const bool earlier = g_rendered_here.count(dir) == 0;
    g_tally.reused_from_earlier_run += earlier;
    return {true, earlier, 0, 0};
  }
  fs::remove_all(dir);
  render::Scenario s = render::load_scenario(scenario_path);
  tweak(s);
  render::RenderOptions ro;
  ro.threads = threads;
  const render::RenderSummary sum = render::render_recording(s, dir, ro);
  // Without its stamp a render is done again next time; a stamp that cannot
  // be written is a failing disk, said now rather than ignored.
  write_file(stamp_path(dir), stamp, "the render's stamp");
  std::lock_guard<std::mutex> lock(g_mu);
  g_rendered_here.insert(dir);
  ++g_tally.rendered;
  g_tally.seconds += sum.seconds;
  return {false, false, sum.frames, sum.seconds};
}

RenderTally render_tally() {
  std::lock_guard<std::mutex> lock(g_mu);
  return g_tally;
}

}  // namespace lumavel::host::reproduce
