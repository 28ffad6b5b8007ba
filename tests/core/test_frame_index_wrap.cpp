// The frame index wraps at 2^32 (2.3 years at 60 Hz, 50 days at 1 kHz):
// nothing but the index may change there. It used to stand for "there was
// a previous frame", so the heading fell back to the raw gyro integral at
// the wrap: a permanent jump of the learned offset times the uptime.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "lumavel/core/estimator.hpp"
#include "lumavel/host/settings.hpp"
#include "synthetic_rig.hpp"

using namespace lumavel;

TEST_GROUP(FrameIndexWrap){};

TEST(FrameIndexWrap, EstimatesAcrossTheWrapEqualThoseOfARunThatDoesNotWrap) {
  test::SyntheticRig rig;
  rig.noise = 1.0;
  const EstimatorConfig cfg = host::to_fixed_config(rig.settings());
  auto plain = std::make_unique<Estimator>(), wrapping = std::make_unique<Estimator>();
  CHECK(plain->configure(cfg) == ConfigError::kOk);
  CHECK(wrapping->configure(cfg) == ConfigError::kOk);
  constexpr uint32_t kStart = 0xFFFFFFFFu - 119;  // the 121st frame gets index 0
  wrapping->set_next_frame_index(kStart);
  const double offset = 0.02;  // rad/s, learned during the first second
  double x = 0, th = 0;
  int wrapped_at = -1;
  RateQ24 learned = 0;
  for (int i = 0; i < 180; ++i) {
    const double t = i / 60.0;
    const bool moving = t > 1.0;
    const double omega = moving ? 0.1 : 0;
    x += moving ? 0.5 / 60 : 0;
    th += omega / 60;
    for (int g = 1; g <= 4; ++g) {
      const double tg = t - 1 / 60.0 + g / 240.0;
      if (tg < 0) continue;
      const uint64_t tn = static_cast<uint64_t>(std::llround(tg * 1e9));
      const RateQ24 r = static_cast<RateQ24>(std::lround(std::ldexp(omega + offset, 24)));
      plain->push_gyro(tn, r);
      wrapping->push_gyro(tn, r);
    }
    const auto a = rig.render(0, {x, 0, th}), b = rig.render(1, {x, 0, th});
    const FramePair f{static_cast<uint64_t>(std::llround(t * 1e9)), {a.data(), b.data()}, static_cast<uint16_t>(rig.width)};
    const Estimate p = plain->step(f), w = wrapping->step(f);
    LONGS_EQUAL(static_cast<uint32_t>(i), p.frame_index);
    CHECK_EQUAL(static_cast<uint32_t>(kStart + static_cast<uint32_t>(i)), w.frame_index);
    if (w.frame_index == 0) wrapped_at = i;
    LONGS_EQUAL(p.heading, w.heading);
    LONGS_EQUAL(p.v, w.v);
    CHECK(p.distance == w.distance);
    LONGS_EQUAL(p.status, w.status);
    LONGS_EQUAL(p.gyro_offset, w.gyro_offset);
    learned = p.gyro_offset;
  }
  LONGS_EQUAL(120, wrapped_at);
  std::printf("\n  wrapped at frame 120 with a learned offset of %.4f rad/s: estimates unchanged",
              std::ldexp(learned, -24));
  CHECK(std::fabs(std::ldexp(learned, -24) - offset) < 1e-3);  // the case that used to jump
}
