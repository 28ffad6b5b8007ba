#include "lumavel/host/vo_engine.hpp"

#include "lumavel/host/vo/stereo_vo.hpp"

namespace lumavel::host {
namespace {

class VoEngine final : public Engine {
 public:
  // One thread, like lumavel's engines: OpenCV's own thread pool would
  // make the compute time per frame incomparable.
  explicit VoEngine(const vo::StereoRig& rig) : vo_(rig) { cv::setNumThreads(1); }
  void push_gyro(uint64_t t_ns, double rate_z) override { vo_.push_gyro(t_ns, rate_z); }
  EngineEstimate step(uint64_t t_ns, const uint8_t* cam0, const uint8_t* cam1) override {
    const vo::VoEstimate v = vo_.step(t_ns, cam0, cam1);
    EngineEstimate e;
    e.t_ns = v.t_ns;
    e.v = v.v;
    e.distance = v.distance;
    e.heading = v.heading;
    e.status = v.status;
    e.v_direct = v.v_direct;
    e.texture = v.inliers;
    return e;
  }

 private:
  vo::StereoVo vo_;
};

}  // namespace

std::unique_ptr<Engine> make_vo_engine(const Recording& rec, int width, int height, bool ignore_distortion) {
  return std::make_unique<VoEngine>(vo::make_stereo_rig(rec, width, height, ignore_distortion));
}

}  // namespace lumavel::host
