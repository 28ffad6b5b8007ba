#include "lumavel/host/file_config_store.hpp"

#include <cstdio>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {

size_t FileConfigStore::load(uint8_t* buf, size_t cap) {
  std::FILE* f = std::fopen(path_.c_str(), "rb");
  if (f == nullptr) return 0;
  const size_t n = std::fread(buf, 1, cap, f);
  const bool more = std::fgetc(f) != EOF;  // larger than cap: not ours
  std::fclose(f);
  return more ? 0 : n;
}

bool FileConfigStore::save(const uint8_t* buf, size_t len) {
  // The one temporary-name rule of the outputs (was: PATH.tmp, too long a
  // name for a 252- to 255-byte store name, whose every save then failed).
  const std::string tmp = temporary_name_for(path_);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) return false;
  const bool ok = std::fwrite(buf, 1, len, f) == len;
  if (std::fclose(f) != 0 || !ok) return false;
  return std::rename(tmp.c_str(), path_.c_str()) == 0;
}

}  // namespace lumavel::host
