// hidapi, loaded at run time: the hidraw and libusb builds of hidapi export
// the same symbols, so the backend (--backend) is chosen by dlopen()ing one.
#pragma once
#include <hidapi/hidapi.h>

#include <string>

namespace lumavel::read {

enum class Backend { kHidraw, kLibusb };

struct HidApi {
  Backend backend;
  int (*init)();
  int (*exit)();
  hid_device_info* (*enumerate)(unsigned short, unsigned short);
  void (*free_enumeration)(hid_device_info*);
  hid_device* (*open_path)(const char*);
  void (*close)(hid_device*);
  int (*read_timeout)(hid_device*, unsigned char*, size_t, int);
  int (*send_feature_report)(hid_device*, const unsigned char*, size_t);
  int (*get_feature_report)(hid_device*, unsigned char*, size_t);
  const wchar_t* (*error)(hid_device*);
};

// Throws std::runtime_error naming the library and the package to install.
const HidApi& load_hidapi(Backend b);
// Makes load_hidapi return `stand_in` instead (nullptr: the real backends
// again): a stand-in device for tests of the commands over a misbehaving link.
void use_stand_in_hidapi(const HidApi* stand_in);
Backend parse_backend(const std::string& name);  // "hidraw" | "libusb"; throws
const char* backend_name(Backend b);
std::string narrow(const wchar_t* s);  // "" for null

}  // namespace lumavel::read
