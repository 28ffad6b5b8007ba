#include <CppUTest/TestHarness.h>

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "lumavel/host/file_config_store.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/report_file.hpp"
#include "lumavel/protocol/reports.hpp"

using namespace lumavel;

namespace {

std::string temp_path(const char* name) {
  return std::string("/tmp/lumavel_hid_test_") + std::to_string(::getpid()) + "_" + name;
}

bool contains(const std::string& s, const char* part) { return s.find(part) != std::string::npos; }

std::string open_error(const std::string& spec) {
  try {
    host::open_host_link(spec);
  } catch (const host::HidLinkError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(HostLinks){};

TEST(HostLinks, FileLinkWritesWhatReplayReads) {
  const std::string path = temp_path("stream.hidrep");
  std::vector<std::vector<uint8_t>> sent;
  {
    auto link = host::open_host_link("file:" + path);
    for (uint16_t i = 0; i < 5; ++i) {
      protocol::Measurement m{};
      m.seq = i;
      m.t_ns = 1000u * i;
      m.v = 65536 * i;
      std::vector<uint8_t> r(protocol::kMeasurementSize);
      protocol::encode_measurement(m, r.data(), r.size());
      CHECK_TRUE(link->send_input(r.data(), r.size()));
      sent.push_back(r);
    }
    link->poll_features([](void*, uint8_t, bool, uint8_t*, size_t, size_t) -> size_t { return 0; },
                        nullptr);
  }
  host::ReportFileReader in(path);
  std::vector<uint8_t> r;
  size_t n = 0;
  while (in.next(r)) {
    CHECK_TRUE(n < sent.size());
    CHECK_TRUE(r == sent[n]);
    ++n;
  }
  CHECK_EQUAL(sent.size(), n);
  std::remove(path.c_str());
}

// A report file of one good record (1, 2, 3) followed by `tail` as written, and
// a reader past that record.
static std::unique_ptr<host::ReportFileReader> past_one_record(const std::string& path, const uint8_t* tail, size_t n) {
  {
    host::ReportFileWriter w(path);
    const uint8_t a[3] = {1, 2, 3};
    w.write(a, 3);
  }
  std::FILE* f = std::fopen(path.c_str(), "ab");
  std::fwrite(tail, 1, n, f);
  std::fclose(f);
  auto in = std::make_unique<host::ReportFileReader>(path);
  std::vector<uint8_t> r;
  CHECK_TRUE(in->next(r));
  return in;
}

TEST(HostLinks, TruncatedReportFileNamesRecordAndOffset) {
  const std::string path = temp_path("cut.hidrep");
  const uint8_t partial[3] = {10, 1, 2};  // says 10 bytes, has 2
  const auto in = past_one_record(path, partial, sizeof partial);
  std::vector<uint8_t> r;
  try {
    in->next(r);
    FAIL("truncated record accepted");
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    CHECK_TRUE(contains(m, "record 2"));
    CHECK_TRUE(contains(m, "byte 12"));
    CHECK_TRUE(contains(m, "truncated"));
  }
  std::remove(path.c_str());
}

// A CSV where a report file was expected.
static void write_csv_instead(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  std::fputs("timestamp_ns,v\n", f);
  std::fclose(f);
}

TEST(HostLinks, NotAReportFile) {
  const std::string path = temp_path("junk");
  write_csv_instead(path);
  try {
    host::ReportFileReader in(path);
    FAIL("accepted");
  } catch (const std::runtime_error& e) {
    CHECK_TRUE(contains(e.what(), "not a lumavel report file"));
  }
  std::remove(path.c_str());
}

// The file's name is shown as every name is (shown_path): a report file named
// 'r<ESC>[2J.hidrep' cleared the terminal of lumavel-read replay with 'not a
// lumavel report file' and with a damaged record's refusal.
TEST(HostLinks, AReportFilesNameIsShownLikeAField) {
  const std::string path = temp_path("r\x1b[2J.hidrep");
  const std::string shown = temp_path("r\\x1B[2J.hidrep");
  write_csv_instead(path);
  try {
    host::ReportFileReader in(path);
    FAIL("accepted");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL((shown + ": not a lumavel report file (no \"LMVHID1\" header)").c_str(), e.what());
  }
  const uint8_t empty[1] = {0};  // a zero-length record
  const auto in = past_one_record(path, empty, sizeof empty);
  std::vector<uint8_t> r;
  try {
    in->next(r);
    FAIL("a zero-length record accepted");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL((shown + ": record 2 at byte 12: zero-length record").c_str(), e.what());
  }
  std::remove(path.c_str());
}

TEST(HostLinks, ErrorsNameTheDeviceAndSayWhatToDo) {
  const std::string unknown = open_error("usb:foo");
  CHECK_TRUE(contains(unknown, "usb:foo"));
  CHECK_TRUE(contains(unknown, "hidg"));
  const std::string uhid = open_error("uhid:/nonexistent/uhid");
  CHECK_TRUE(contains(uhid, "/nonexistent/uhid"));
  CHECK_TRUE(contains(uhid, "modprobe uhid"));
  const std::string hidg = open_error("hidg:/nonexistent/hidg7");
  CHECK_TRUE(contains(hidg, "/nonexistent/hidg7"));
  CHECK_TRUE(contains(hidg, "configfs"));
  // A regular file is no device node: written over, and uhid then hung (was: exit 0 for hidg, a hang for uhid).
  const std::string plain = temp_path("plain.txt");
  std::FILE* f = std::fopen(plain.c_str(), "wb");
  std::fputs("keep me\n", f);
  std::fclose(f);
  CHECK_TRUE(contains(open_error("hidg:" + plain), "plain.txt: is a regular file, not a HID gadget device node"));
  CHECK_TRUE(contains(open_error("uhid:" + plain), "plain.txt: is a regular file, not a uhid device node"));
  f = std::fopen(plain.c_str(), "rb");
  char kept[16] = {0};
  CHECK_TRUE(std::fgets(kept, sizeof kept, f) != nullptr);
  std::fclose(f);
  STRCMP_EQUAL("keep me\n", kept);
  std::remove(plain.c_str());
  // Another device node (was: hidg read /dev/zero as host requests for ever,
  // a hang; uhid took its UHID_CREATE2 write and waited 30 s for a host).
  // Where sysfs names the node, that is: without sysfs nothing can tell.
  if (!host::char_device_of("/dev/zero").subsystem.empty()) {
    CHECK_TRUE(contains(open_error("hidg:/dev/zero"),
                        "/dev/zero: is the character device 1:5 (mem zero), not a HID gadget device node"));
    CHECK_TRUE(contains(open_error("uhid:/dev/null"),
                        "/dev/null: is the character device 1:3 (mem null), not a uhid device node"));
  }
  const std::string file = open_error("file:/nonexistent/dir/x.hidrep");
  CHECK_TRUE(contains(file, "/nonexistent/dir/x.hidrep"));
  CHECK_TRUE(contains(open_error("file:"), "needs a path"));
}

TEST(HostLinks, FileConfigStoreRoundTrips) {
  const std::string path = temp_path("store.bin");
  host::FileConfigStore s(path);
  uint8_t buf[8];
  CHECK_EQUAL(0u, s.load(buf, sizeof buf));  // nothing stored yet
  const uint8_t blob[5] = {9, 8, 7, 6, 5};
  CHECK_TRUE(s.save(blob, sizeof blob));
  CHECK_EQUAL(5u, s.load(buf, sizeof buf));
  MEMCMP_EQUAL(blob, buf, 5);
  CHECK_EQUAL(0u, s.load(buf, 4));  // larger than the caller's buffer: not ours
  std::remove(path.c_str());
  // A store named as long as a name may be (255 bytes) is saved: its
  // temporary name, the name and '.tmp', was too long, and every save failed.
  std::string name = "lumavel_hid_test_" + std::to_string(::getpid()) + "_";
  name.resize(251, 's');
  const std::string longest = "/tmp/" + name + ".bin";
  host::FileConfigStore l(longest);
  CHECK_TRUE(l.save(blob, sizeof blob));
  CHECK_EQUAL(5u, l.load(buf, sizeof buf));
  std::remove(longest.c_str());
}
