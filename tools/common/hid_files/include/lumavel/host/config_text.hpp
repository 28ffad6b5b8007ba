// A device configuration with its lens tables as KEY=VALUE text in physical
// units: what `lumavel-read config get` prints, `config set` and
// `config set --file` read, and `lumavel-sim calibrate --write` writes.
// Values print as the shortest decimals that convert back to the same
// fixed-point numbers, so get -> set is lossless.
#pragma once
#include <string>
#include <vector>

#include "lumavel/core/fixed.hpp"
#include "lumavel/protocol/device_config.hpp"

namespace lumavel::host {

struct DeviceSetup {
  protocol::DeviceConfig config{};
  // Lens correction per camera (width + 1 values, EdgeOffsetQ15); empty = pinhole.
  std::vector<EdgeOffsetQ15> lens[2];
};

// One KEY=VALUE per line, every key, in a fixed order (lens_camN=none
// for a camera without a table).
std::string format_setup(const DeviceSetup& s);
// Applies "KEY=VALUE" (spaces around KEY, = and VALUE allowed); throws
// std::runtime_error naming the key and the accepted form. Ranges are
// checked afterwards (check_settings_offline, check_settings).
void apply_setting(DeviceSetup& s, const std::string& kv);
// Applies every KEY=VALUE line of `text` (blank lines and # comments
// skipped, a UTF-8 byte-order mark at the start ignored); errors are
// prefixed with "NAME:LINE: ".
void apply_settings_text(DeviceSetup& s, const std::string& text, const std::string& name);
// Reads FILE and applies it; throws naming the file (and line) on failure,
// e.g. when FILE is a directory.
void apply_settings_file(DeviceSetup& s, const std::string& path);

// KEY=VALUE settings in the order given, each with where it came from
// ("rig.cfg:3", "command line"), so that a refusal names it.
struct GivenSetting {
  std::string where, key, value;
};
struct GivenSettings {
  std::vector<GivenSetting> items;
  // Parses "KEY=VALUE" (its value is checked by apply_setting); throws
  // "WHERE: ..." when it does not parse.
  void add(const std::string& kv, const std::string& where);
  // Every setting line of FILE (as apply_settings_file reads it); refuses a
  // key given twice in the file and a file without any setting.
  void add_file(const std::string& path);
  // The command line's KEY=VALUE settings ("command line"); refuses a key
  // given twice among them.
  void add_command_line(const std::vector<std::string>& settings);
  void apply_to(DeviceSetup& s) const;  // in order (seal_lens afterwards)
  bool has(const std::string& key) const;

 private:
  const GivenSetting* given_before(size_t first) const;
};

// Checks what can be checked without a device: every given key against its
// range, and the rules between given keys (fu and cu against a given width,
// lens tables against it, max_gap_us against frame_period_us). Keys not
// given are taken at their most permissive value, so nothing valid is
// refused. Throws std::runtime_error "WHERE: KEY = VALUE: RULE".
void check_settings_offline(const GivenSettings& given);

// Checks `base` (e.g. the device's configuration) with `given` applied:
// returns "" or the refusal, naming the given key responsible ("WHERE: KEY
// = VALUE: RULE"), or the field when none is ("fu0_px, fu1_px: RULE").
std::string check_settings(const DeviceSetup& base, const GivenSettings& given);
// Sets config.lens and config.lens_crc from the tables. Throws naming the
// key (lens_camN) when a table's length is not width + 1.
void seal_lens(DeviceSetup& s);
const char* config_keys_help();

}  // namespace lumavel::host
