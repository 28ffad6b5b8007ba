#include "hidapi_loader.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace lumavel::read {

namespace {

template <typename F>
void bind(void* lib, const char* name, F& fn, const std::string& so) {
  fn = reinterpret_cast<F>(dlsym(lib, name));
  if (fn == nullptr) throw std::runtime_error(so + " has no " + name + " (hidapi too old?)");
}

HidApi load(Backend b) {
  const std::string so =
      b == Backend::kHidraw ? "libhidapi-hidraw.so.0" : "libhidapi-libusb.so.0";
  void* lib = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (lib == nullptr) {
    throw std::runtime_error("cannot load " + so + " (" + dlerror() + "): install Debian package " +
                             (b == Backend::kHidraw ? "libhidapi-hidraw0" : "libhidapi-libusb0"));
  }
  HidApi h{};
  h.backend = b;
  bind(lib, "hid_init", h.init, so);
  bind(lib, "hid_exit", h.exit, so);
  bind(lib, "hid_enumerate", h.enumerate, so);
  bind(lib, "hid_free_enumeration", h.free_enumeration, so);
  bind(lib, "hid_open_path", h.open_path, so);
  bind(lib, "hid_close", h.close, so);
  bind(lib, "hid_read_timeout", h.read_timeout, so);
  bind(lib, "hid_send_feature_report", h.send_feature_report, so);
  bind(lib, "hid_get_feature_report", h.get_feature_report, so);
  bind(lib, "hid_error", h.error, so);
  if (h.init() != 0) throw std::runtime_error(so + ": hid_init failed");
  return h;  // the library stays loaded for the life of the process
}

const HidApi* g_stand_in = nullptr;

}  // namespace

void use_stand_in_hidapi(const HidApi* stand_in) { g_stand_in = stand_in; }

const HidApi& load_hidapi(Backend b) {
  if (g_stand_in != nullptr) return *g_stand_in;
  static const HidApi hidraw = b == Backend::kHidraw ? load(b) : HidApi{};
  static const HidApi libusb = b == Backend::kLibusb ? load(b) : HidApi{};
  const HidApi& h = b == Backend::kHidraw ? hidraw : libusb;
  if (h.init == nullptr) throw std::runtime_error("one hidapi backend per process");
  return h;
}

Backend parse_backend(const std::string& name) {
  if (name == "hidraw") return Backend::kHidraw;
  if (name == "libusb") return Backend::kLibusb;
  throw std::runtime_error("unknown --backend \"" + name + "\" (use hidraw or libusb)");
}

const char* backend_name(Backend b) { return b == Backend::kHidraw ? "hidraw" : "libusb"; }

std::string narrow(const wchar_t* s) {
  std::string out;
  if (s == nullptr) return out;
  for (; *s != 0; ++s) out += (*s >= 0x20 && *s < 0x7F) ? static_cast<char>(*s) : '?';
  return out;
}

}  // namespace lumavel::read
