// Device-side handling of the feature reports, ready to pass to
// hal::ReportLink::poll_features: device info (get), configuration (get/set:
// CRC, version, ranges, lens tables, then the application's apply hook, then
// the store) and lens table pieces (set: upload or select; get).
// A stateful device service over the codec, so it lives in the app, not in
// firmware/protocol (the codec knows no HAL). Integer only, no heap.
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/hal/config_store.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/lens.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::app {

class FeatureServer {
 public:
  // Applies a range-checked configuration (e.g. rebuilds the estimator) with
  // its lens tables (lens[i] is null unless cfg.lens names camera i; complete
  // and matching cfg.lens_crc). Returns kOk, or the refusal (kEstimator,
  // kLensEdges, ...) if it did not apply (nothing changes then).
  using ApplyFn = protocol::ConfigField (*)(void* ctx, const protocol::DeviceConfig& cfg,
                                            const EdgeOffsetQ15* const lens[2]);

  // `identity` gives firmware version, board and capacities; the working
  // resolution and config status/source are kept up to date by the server.
  FeatureServer(const protocol::DeviceInfo& identity, hal::ConfigStore* store, ApplyFn apply, void* ctx);

  // At boot: the stored configuration (with its lens tables) if it decodes
  // and applies, else `defaults` (which must apply and have no lens).
  // Returns the status of `defaults` if even that fails.
  protocol::ConfigField boot(const protocol::DeviceConfig& defaults);

  // hal::ReportLink::FeatureHandler; ctx is the FeatureServer.
  static size_t handle(void* ctx, uint8_t id, bool is_set, uint8_t* buf, size_t len, size_t cap);

  // Set from the host: decode, validate, check the lens tables it names,
  // apply, persist. Returns the outcome, also reported in DeviceInfo.config_status.
  protocol::ConfigField set_config(const uint8_t* buf, size_t len);
  // A lens piece from the host (report 0x05): kMalformed if it does not
  // decode, kLens if it breaks the upload order or the build's capacity;
  // reported in DeviceInfo.lens_status. Pieces are staged apart from the
  // tables in force; the next configuration set takes the staged tables
  // only if its lens_crc names them, and ends the upload either way (the
  // staging starts clean again), so an upload that was never applied can
  // never be applied by a later, unrelated set. A select (count 0) picks
  // the piece of the tables in force that a get returns.
  protocol::ConfigField set_lens(const uint8_t* buf, size_t len);

  const protocol::DeviceConfig& config() const { return config_; }
  const protocol::DeviceInfo& info() const { return info_; }
  // The tables in force (those config() names, by lens_crc).
  const protocol::LensTables& lens() const { return lens_; }
  // Pieces uploaded since the last configuration set.
  const protocol::LensTables& staged() const { return staged_; }

 private:
  protocol::ConfigField apply_and_keep(const protocol::DeviceConfig& c, uint8_t source);
  // For each camera c names: the staged table (preferred) or the one in
  // force, whichever makes the CRC c.lens_crc names. False if none does.
  bool pick_tables(const protocol::DeviceConfig& c, const EdgeOffsetQ15* tables[2]) const;
  void end_upload();
  bool load_stored(protocol::DeviceConfig& out);  // the stored blob into out and lens_
  bool save_current();                            // config_ and its tables into the store

  protocol::DeviceInfo info_;
  protocol::DeviceConfig config_{};
  protocol::LensTables lens_{};    // in force
  protocol::LensTables staged_{};  // uploaded, not yet taken by a configuration set
  hal::ConfigStore* store_;
  ApplyFn apply_;
  void* ctx_;
};

}  // namespace lumavel::app
