// The report link: input reports out, feature (configuration) requests in.
// Byte layouts belong to the one HID codec in firmware/protocol.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lumavel::hal {

class ReportLink {
 public:
  virtual ~ReportLink() = default;
  // Sends one input report (report ID first). False if it could not be queued.
  virtual bool send_input(const uint8_t* report, size_t len) = 0;
  // Serves pending feature requests through `handler`; never blocks.
  // The handler gets (report id, set?, buffer, length in, capacity) and returns
  // the reply length for a get (0 to stall), or 0/1 (rejected/accepted) for a set.
  using FeatureHandler = size_t (*)(void* ctx, uint8_t id, bool is_set, uint8_t* buf,
                                    size_t len, size_t cap);
  virtual void poll_features(FeatureHandler handler, void* ctx) = 0;
};

}  // namespace lumavel::hal
