#include "render_cache.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lumavel/host/render/recording_renderer.hpp"
#include "lumavel/host/render/scenario_loader.hpp"

namespace lumavel::host::reproduce {
namespace fs = std::filesystem;

CachedRender render_cached(const std::string& scenario_path, const std::string& dir, const std::string& key,
                           const std::function<void(render::Scenario&)>& tweak, int threads) {
  std::ostringstream stamp;
  stamp << scenario_path << " " << fs::last_write_time(scenario_path).time_since_epoch().count() << " " << key
        << "\n";
  const std::string stamp_path = dir + "/.render-stamp";
  {
    std::ifstream in(stamp_path);
    std::stringstream have;
    have << in.rdbuf();
    if (in && have.str() == stamp.str()) return {true, 0, 0};
  }
  fs::remove_all(dir);
  render::Scenario s = render::load_scenario(scenario_path);
  tweak(s);
  render::RenderOptions ro;
  ro.threads = threads;
  const render::RenderSummary sum = render::render_recording(s, dir, ro);
  std::ofstream(stamp_path) << stamp.str();
  return {false, sum.frames, sum.seconds};
}

}  // namespace lumavel::host::reproduce
