// Configuration blob in the last 1 KiB flash page (0x0800FC00, kept out of
// the image by the linker script): u16 magic, u16 length, the bytes. The blob
// carries its own CRC (protocol::decode_config checks it).
#pragma once
#include <cstddef>
#include <cstdint>

#include "lumavel/hal/config_store.hpp"

namespace bluepill {

class FlashStore final : public lumavel::hal::ConfigStore {
 public:
  size_t load(uint8_t* buf, size_t cap) override;
  bool save(const uint8_t* buf, size_t len) override;
};

}  // namespace bluepill
