// hidg: the device side of the Linux USB gadget HID function (/dev/hidgN,
// configured with no_out_endpoint=1 so that SET_REPORT data reaches read()).
// The 6.1 gadget answers GET_REPORT itself with zeros, so feature reads go
// through the mailbox: the host sets report 0x04 naming the feature report
// and the link sends it back as input reports 0x84 (see docs/usb-hid.md).
#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <deque>

#include "links.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/protocol/reports.hpp"

namespace lumavel::host {

namespace {

namespace proto = lumavel::protocol;

class HidgLink : public hal::ReportLink {
 public:
  explicit HidgLink(const std::string& path) : path_(path) {
    // Another device was read as the host's requests: /dev/zero never ran
    // dry and poll_features read it for ever (the run hung).
    refuse_if_not_a_device(path, "HID gadget device node (/dev/hidgN)", "hidg", "");
    fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) {
      const int e = errno;
      if (e == ENOENT || e == ENODEV || e == ENXIO) {
        throw HidLinkError(path + " not found: create and bind a configfs HID gadget "
                                  "(usb_f_hid, see docs/usb-hid.md) first");
      }
      if (e == EACCES || e == EPERM) {
        throw HidLinkError(path + ": permission denied: run as root or grant access to " + path);
      }
      throw HidLinkError(path + ": cannot open: " + std::strerror(e));
    }
  }
  ~HidgLink() override { ::close(fd_); }

  bool send_input(const uint8_t* report, size_t len) override {
    if (!flush_outbox()) return false;  // mailbox replies go first
    return write_report(report, len);
  }

  void poll_features(FeatureHandler handler, void* ctx) override {
    uint8_t buf[512];
    for (;;) {
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n <= 0) break;  // EAGAIN: nothing pending
      const size_t len = static_cast<size_t>(n);
      uint8_t id = 0, tag = 0;
      if (proto::decode_mailbox_request(buf, len, id, tag).ok()) {
        queue_reply(id, tag, handler, ctx);
      } else {
        // The USB host already has its ACK; the outcome shows in DeviceInfo.config_status.
        handler(ctx, buf[0], true, buf, len, sizeof buf);
      }
    }
    flush_outbox();
  }

 private:
  using Chunk = std::array<uint8_t, proto::kFeatureChunkSize>;

  bool write_report(const uint8_t* report, size_t len) {
    for (;;) {
      const ssize_t n = ::write(fd_, report, len);
      if (n == static_cast<ssize_t>(len)) return true;
      if (n < 0 && errno == EINTR) continue;
      return false;  // EAGAIN: the previous report is still waiting for the host
    }
  }

  void queue_reply(uint8_t id, uint8_t tag, FeatureHandler handler, void* ctx) {
    uint8_t report[proto::kMaxReportSize + 1];
    report[0] = id;
    const size_t n = handler(ctx, id, false, report, 0, proto::kMaxReportSize);
    if (n == 0 || n > proto::kMaxReportSize) return;  // the host times out: a stall
    for (size_t i = 0; i < proto::feature_chunk_count(n); ++i) {
      Chunk bytes{};
      proto::encode_feature_chunk(proto::feature_chunk(report, n, tag, i), bytes.data(), bytes.size());
      outbox_.push_back(bytes);
    }
  }

  bool flush_outbox() {
    while (!outbox_.empty()) {
      if (!write_report(outbox_.front().data(), outbox_.front().size())) return false;
      outbox_.pop_front();
    }
    return true;
  }

  std::string path_;
  int fd_ = -1;
  std::deque<Chunk> outbox_;
};

}  // namespace

std::unique_ptr<hal::ReportLink> make_hidg_link(const std::string& path) {
  return std::make_unique<HidgLink>(path);
}

}  // namespace lumavel::host
