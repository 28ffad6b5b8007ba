// lumavel-read's `config set`, `config get` and `info` against the firmware
// application over a link that loses chosen transfers or goes away in the
// middle of a lens upload (StandInDevice). Whatever happened before, the
// device keeps answering get and set (the repairing set included), `info`
// tells the truth, and a table that was uploaded but never applied is never
// applied by a later, unrelated set. Over the mailbox, a stale answer (the
// previous one, replayed) is never taken as current.
#include <CppUTest/TestHarness.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "device.hpp"
#include "lumavel/host/config_text.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "stand_in_device.hpp"

using lumavel::EdgeOffsetQ15;
using lumavel::test::StandInDevice;
namespace lr = lumavel::read;
namespace protocol = lumavel::protocol;

namespace {

struct Outcome {
  int exit = -1;          // the command's exit code; -1: it threw DeviceError
  std::string out;        // its standard output
};

// Runs one lumavel-read command with stdout captured.
template <typename F>
Outcome run(F command) {
  std::fflush(stdout);
  const int saved = dup(1);
  FILE* tmp = std::tmpfile();
  dup2(fileno(tmp), 1);
  Outcome o;
  try {
    o.exit = command();
  } catch (const lr::DeviceError& e) {
    std::fprintf(stderr, "  (lumavel-read: %s)\n", e.what());
  }
  std::fflush(stdout);
  dup2(saved, 1);
  ::close(saved);
  std::rewind(tmp);
  char buf[4096];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, tmp)) > 0) o.out.append(buf, n);
  std::fclose(tmp);
  return o;
}

// `config get` or `config set KEY=VALUE...`, as main.cpp dispatches them.
Outcome config(const std::vector<std::string>& args) {
  if (!args.empty() && args[0] == "get") return run([] { return lr::cmd_config_get(lr::Common{}); });
  lr::ConfigInput in;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--file" && i + 1 < args.size()) in.files.push_back(args[++i]);
    else in.settings.push_back(args[i]);
  }
  return run([&] { return lr::cmd_config_set(lr::Common{}, in); });
}
Outcome info() {
  return run([] { return lr::cmd_info(lr::Common{}); });
}

// A smooth table of 41 corrections (the default 40-column configuration).
std::vector<EdgeOffsetQ15> lens_table(int scale) {
  std::vector<EdgeOffsetQ15> t;
  for (int u = 0; u <= 40; ++u) {
    const int x = 2 * u - 40;
    t.push_back(static_cast<EdgeOffsetQ15>(scale * x * x * x / 64000));
  }
  return t;
}

// "lens_cam0=..." as `config get` prints it.
std::string lens_setting(const std::vector<EdgeOffsetQ15>& t) {
  lumavel::host::DeviceSetup s;
  s.lens[0] = t;
  const std::string all = lumavel::host::format_setup(s);
  const size_t at = all.find("lens_cam0=");
  return all.substr(at, all.find('\n', at) - at);
}

bool in_force(StandInDevice& d, const std::vector<EdgeOffsetQ15>& t) {
  const protocol::LensTables& l = d.app().lens_tables();
  if (l.filled[0] != t.size()) return false;
  for (size_t i = 0; i < t.size(); ++i)
    if (l.offsets[0][i] != t[i]) return false;
  return true;
}

bool has(const std::string& text, const std::string& line) { return text.find(line + "\n") != std::string::npos; }

}  // namespace

TEST_GROUP(FlakyLink) {
  std::vector<EdgeOffsetQ15> a = lens_table(300), b = lens_table(-200);
};

TEST(FlakyLink, ALostLensPieceIsSentAgain) {
  StandInDevice dev;
  dev.drop = {3};  // the set reads the configuration (1), then sends the pieces: 3 is the second
  const Outcome o = config({"set", lens_setting(a)});
  LONGS_EQUAL(lr::kExitOk, o.exit);
  CHECK_TRUE(in_force(dev, a));
  CHECK_TRUE(has(o.out, lens_setting(a)));
}

TEST(FlakyLink, HostGoneMidUploadLeavesTheDeviceAnsweringAndTruthful) {
  StandInDevice dev;
  LONGS_EQUAL(lr::kExitOk, config({"set", lens_setting(a)}).exit);
  // A new table: the host goes away after the first piece of it.
  const int start = dev.transfers();
  dev.gone_after = start + 6;  // the read-back of the setup (config, 2 x select + get), then one piece
  LONGS_EQUAL(-1, config({"set", lens_setting(b)}).exit);
  dev.reconnect();
  // info: the last set was accepted (a), and an upload is pending on camera 0.
  const Outcome i = info();
  LONGS_EQUAL(lr::kExitOk, i.exit);
  CHECK_TRUE(has(i.out, "last_config_set=ok"));
  CHECK_TRUE(has(i.out, "lens_upload_pending=cam0"));
  // get answers with the table in force.
  const Outcome g = config({"get"});
  LONGS_EQUAL(lr::kExitOk, g.exit);
  CHECK_TRUE(has(g.out, lens_setting(a)));
  // An unrelated set goes through and keeps a.
  const Outcome u = config({"set", "tau_us=150000"});
  LONGS_EQUAL(lr::kExitOk, u.exit);
  CHECK_TRUE(in_force(dev, a));
  CHECK_EQUAL(150000u, dev.app().device_config().tau_us);
  CHECK_TRUE(has(info().out, "lens_upload_pending=none"));
  // The repairing set: table b in full.
  LONGS_EQUAL(lr::kExitOk, config({"set", lens_setting(b)}).exit);
  CHECK_TRUE(in_force(dev, b));
}

TEST(FlakyLink, AnUploadedButNeverAppliedTableIsNotAppliedByALaterSet) {
  StandInDevice dev;
  LONGS_EQUAL(lr::kExitOk, config({"set", lens_setting(a)}).exit);
  // Table b uploaded in full, then the host goes away before its configuration.
  const int start = dev.transfers();
  dev.gone_after = start + 5 + 2;  // the read-back of the setup, then both pieces of b
  LONGS_EQUAL(-1, config({"set", lens_setting(b)}).exit);
  dev.reconnect();
  CHECK_TRUE(has(info().out, "lens_upload_pending=cam0"));
  // Later an unrelated set: the device's table is still a, and stays a.
  LONGS_EQUAL(lr::kExitOk, config({"set", "tau_us=120000"}).exit);
  CHECK_TRUE(in_force(dev, a));
  CHECK_TRUE(has(config({"get"}).out, lens_setting(a)));
}

TEST(FlakyLink, AStaleMailboxAnswerIsNeverTakenAsCurrent) {
  StandInDevice dev;
  dev.gadget = true;        // every read through the mailbox
  dev.replay_stale = true;  // each answer preceded by the previous one
  LONGS_EQUAL(lr::kExitOk, config({"set", "tau_us=150000", lens_setting(a)}).exit);
  LONGS_EQUAL(lr::kExitOk, config({"set", "tau_us=170000"}).exit);
  const Outcome g = config({"get"});
  LONGS_EQUAL(lr::kExitOk, g.exit);
  CHECK_TRUE(has(g.out, "tau_us=170000"));
  CHECK_TRUE(has(g.out, lens_setting(a)));
  const Outcome i = info();
  CHECK_TRUE(has(i.out, "last_config_set=ok"));
}
