// Scriptable HAL fakes for the app tests: frames at given times, gyro samples
// at given times, a report link that records what was sent and replays
// queued feature requests, a store that can refuse to save.
#pragma once
#include <cstdint>
#include <vector>

#include "lumavel/hal/camera.hpp"
#include "lumavel/hal/clock.hpp"
#include "lumavel/hal/config_store.hpp"
#include "lumavel/hal/gyro.hpp"
#include "lumavel/hal/report_link.hpp"
#include "lumavel/hal/watchdog.hpp"

namespace fake {

struct Camera : lumavel::hal::StereoCamera {
  uint16_t w = 40, h = 30;
  std::vector<uint64_t> times;  // one frame per entry; UINT64_MAX = capture error
  size_t next = 0;
  uint16_t width() const override { return w; }
  uint16_t height() const override { return h; }
  lumavel::hal::CaptureStatus capture(lumavel::hal::StereoImage& out) override {
    if (next == times.size()) return lumavel::hal::CaptureStatus::kEnd;
    const uint64_t t = times[next++];
    if (t == UINT64_MAX) return lumavel::hal::CaptureStatus::kError;
    out.t_ns = t;
    for (int c = 0; c < 2; ++c)
      for (int i = 0; i < w * h; ++i)
        out.cam[c][i] = static_cast<uint8_t>((i % w) * 5 + c * 3 + static_cast<int>(next) * 2);
    return lumavel::hal::CaptureStatus::kOk;
  }
};

struct Gyro : lumavel::hal::Gyro {
  std::vector<lumavel::hal::GyroSample> samples;
  size_t next = 0;
  size_t ready = SIZE_MAX;  // samples beyond this index are "not yet measured"
  bool read(lumavel::hal::GyroSample& out) override {
    if (next >= samples.size() || next >= ready) return false;
    out = samples[next++];
    return true;
  }
};

struct Clock : lumavel::hal::Clock {
  uint64_t t = 0;
  uint64_t now_ns() override { return t += 1000; }
};

struct Request {
  uint8_t id;
  bool is_set;
  std::vector<uint8_t> data;
};

struct Link : lumavel::hal::ReportLink {
  std::vector<std::vector<uint8_t>> inputs;
  std::vector<Request> pending;
  std::vector<std::vector<uint8_t>> replies;  // get: the report; set: {accepted}
  bool refuse = false;
  bool send_input(const uint8_t* r, size_t n) override {
    if (refuse) return false;
    inputs.emplace_back(r, r + n);
    return true;
  }
  void poll_features(FeatureHandler handler, void* ctx) override {
    for (auto& q : pending) {
      uint8_t buf[128] = {};
      for (size_t i = 0; i < q.data.size(); ++i) buf[i] = q.data[i];
      const size_t n = handler(ctx, q.id, q.is_set, buf, q.data.size(), sizeof buf);
      if (q.is_set)
        replies.push_back({static_cast<uint8_t>(n)});
      else
        replies.emplace_back(buf, buf + n);
    }
    pending.clear();
  }
};

struct Store : lumavel::hal::ConfigStore {
  std::vector<uint8_t> blob;
  bool refuse_save = false;
  int saves = 0;
  size_t load(uint8_t* buf, size_t cap) override {
    if (blob.size() > cap) return 0;
    for (size_t i = 0; i < blob.size(); ++i) buf[i] = blob[i];
    return blob.size();
  }
  bool save(const uint8_t* buf, size_t n) override {
    ++saves;
    if (refuse_save) return false;
    blob.assign(buf, buf + n);
    return true;
  }
};

struct Watchdog : lumavel::hal::Watchdog {
  int kicks = 0;
  void kick() override { ++kicks; }
};

}  // namespace fake
