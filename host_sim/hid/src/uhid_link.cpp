// uhid: the kernel creates a HID device from our descriptor; hidraw readers
// (hidapi) see it as 1209:0001. Feature GET/SET arrive as uhid events.
#include <fcntl.h>
#include <linux/input.h>
#include <linux/uhid.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "links.hpp"
#include "lumavel/host/path_check.hpp"
#include "lumavel/host/hid_link.hpp"
#include "lumavel/protocol/descriptor.hpp"

namespace lumavel::host {

namespace {

namespace proto = lumavel::protocol;

class UhidLink : public hal::ReportLink {
 public:
  explicit UhidLink(const std::string& path) : path_(path) {
    // Another device (/dev/null, a tty) took the UHID_CREATE2 write, never
    // answered, and the first report waited its 30 s for a host in vain.
    refuse_if_not_a_device(path, "uhid device node (/dev/uhid)", "misc", "uhid");
    fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) {
      const int e = errno;
      if (e == ENOENT) {
        throw HidLinkError(path + " does not exist: load the uhid kernel module (`modprobe uhid`), "
                                  "or use --hid hidg:/dev/hidgN or --hid file:PATH");
      }
      if (e == EACCES || e == EPERM) {
        throw HidLinkError(path + ": permission denied: run as root or grant your user "
                                  "read/write access to " + path);
      }
      throw HidLinkError(path + ": cannot open: " + std::strerror(e));
    }
    uhid_event ev{};
    ev.type = UHID_CREATE2;
    std::strncpy(reinterpret_cast<char*>(ev.u.create2.name), "lumavel (uhid)",
                 sizeof ev.u.create2.name - 1);
    std::strncpy(reinterpret_cast<char*>(ev.u.create2.phys), "lumavel-sim",
                 sizeof ev.u.create2.phys - 1);
    std::strncpy(reinterpret_cast<char*>(ev.u.create2.uniq), "sim-0001",
                 sizeof ev.u.create2.uniq - 1);
    std::memcpy(ev.u.create2.rd_data, proto::kReportDescriptor, proto::kReportDescriptorSize);
    ev.u.create2.rd_size = static_cast<uint16_t>(proto::kReportDescriptorSize);
    // hidapi's hidraw backend only enumerates USB/Bluetooth/I2C buses.
    ev.u.create2.bus = BUS_USB;
    ev.u.create2.vendor = proto::kUsbVendorId;
    ev.u.create2.product = proto::kUsbProductId;
    if (!write_event(ev)) {
      const std::string why = std::strerror(errno);
      ::close(fd_);
      throw HidLinkError(path + ": cannot create the virtual HID device: " + why);
    }
  }

  ~UhidLink() override {
    uhid_event ev{};
    ev.type = UHID_DESTROY;
    write_event(ev);
    ::close(fd_);
  }

  // Reports written before the kernel's UHID_OPEN (a reader opened the
  // hidraw node) are dropped by the kernel: refuse them instead.
  bool send_input(const uint8_t* report, size_t len) override {
    pump(nullptr, nullptr);
    if (!open_ || len > UHID_DATA_MAX) return false;
    uhid_event ev{};
    ev.type = UHID_INPUT2;
    ev.u.input2.size = static_cast<uint16_t>(len);
    std::memcpy(ev.u.input2.data, report, len);
    return write_event(ev);
  }

  void poll_features(FeatureHandler handler, void* ctx) override { pump(handler, ctx); }

 private:
  bool write_event(const uhid_event& ev) {
    for (;;) {
      const ssize_t n = ::write(fd_, &ev, sizeof ev);
      if (n == static_cast<ssize_t>(sizeof ev)) return true;
      if (n < 0 && errno == EINTR) continue;
      return false;
    }
  }

  // Reads every pending event. Without a handler (from send_input), feature
  // requests wait in `pending_` for the next poll_features (the kernel gives
  // the reply seconds).
  void pump(FeatureHandler handler, void* ctx) {
    if (handler != nullptr) {
      for (int i = 0; i < pending_count_; ++i) answer(pending_[i], handler, ctx);
      pending_count_ = 0;
    }
    uhid_event ev{};
    while (::read(fd_, &ev, sizeof ev) > 0) {
      switch (ev.type) {
        case UHID_OPEN: open_ = true; break;
        case UHID_CLOSE: open_ = false; break;
        case UHID_GET_REPORT:
        case UHID_SET_REPORT:
          if (handler != nullptr) {
            answer(ev, handler, ctx);
          } else if (pending_count_ < kMaxPending) {
            pending_[pending_count_++] = ev;
          } else {
            reply_error(ev);
          }
          break;
        default: break;  // START, STOP, OUTPUT: nothing to do
      }
    }
  }

  void reply_error(const uhid_event& req) {
    uhid_event r{};
    if (req.type == UHID_GET_REPORT) {
      r.type = UHID_GET_REPORT_REPLY;
      r.u.get_report_reply.id = req.u.get_report.id;
      r.u.get_report_reply.err = EIO;
    } else {
      r.type = UHID_SET_REPORT_REPLY;
      r.u.set_report_reply.id = req.u.set_report.id;
      r.u.set_report_reply.err = EIO;
    }
    write_event(r);
  }

  void answer(const uhid_event& req, FeatureHandler handler, void* ctx) {
    uhid_event r{};
    if (req.type == UHID_GET_REPORT) {
      r.type = UHID_GET_REPORT_REPLY;
      r.u.get_report_reply.id = req.u.get_report.id;
      size_t n = 0;
      if (req.u.get_report.rtype == UHID_FEATURE_REPORT) {
        uint8_t* buf = r.u.get_report_reply.data;
        buf[0] = req.u.get_report.rnum;
        n = handler(ctx, req.u.get_report.rnum, false, buf, 0, UHID_DATA_MAX);
      }
      r.u.get_report_reply.err = n > 0 ? 0 : EIO;
      r.u.get_report_reply.size = static_cast<uint16_t>(n);
    } else {
      r.type = UHID_SET_REPORT_REPLY;
      r.u.set_report_reply.id = req.u.set_report.id;
      size_t ok = 0;
      if (req.u.set_report.rtype == UHID_FEATURE_REPORT) {
        uint8_t buf[UHID_DATA_MAX];
        const size_t len = req.u.set_report.size;
        std::memcpy(buf, req.u.set_report.data, len);
        ok = handler(ctx, req.u.set_report.rnum, true, buf, len, sizeof buf);
      }
      r.u.set_report_reply.err = ok != 0 ? 0 : EIO;
    }
    write_event(r);
  }

  static constexpr int kMaxPending = 8;
  std::string path_;
  int fd_ = -1;
  bool open_ = false;
  uhid_event pending_[kMaxPending]{};
  int pending_count_ = 0;
};

}  // namespace

std::unique_ptr<hal::ReportLink> make_uhid_link(const std::string& path) {
  return std::make_unique<UhidLink>(path);
}

}  // namespace lumavel::host
