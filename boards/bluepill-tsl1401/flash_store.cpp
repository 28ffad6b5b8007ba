#include "flash_store.hpp"

#include "stm32f1.hpp"

namespace bluepill {
namespace {

constexpr uint32_t kPage = 0x0800FC00u;
constexpr uint32_t kPageSize = 1024;
constexpr uint16_t kMagic = 0x564Cu;  // "LV"
constexpr uint32_t kBSY = 1u << 0, kPG = 1u << 0, kPER = 1u << 1, kSTRT = 1u << 6, kLOCK = 1u << 7;

uint16_t half(uint32_t addr) { return *reinterpret_cast<const volatile uint16_t*>(addr); }

void wait_idle() {
  while ((stm32::flash::sr() & kBSY) != 0) {
  }
}

bool program(uint32_t addr, uint16_t v) {
  stm32::flash::cr() = kPG;
  *reinterpret_cast<volatile uint16_t*>(addr) = v;
  wait_idle();
  stm32::flash::cr() = 0;
  return half(addr) == v;
}

}  // namespace

size_t FlashStore::load(uint8_t* buf, size_t cap) {
  if (half(kPage) != kMagic) return 0;
  const uint16_t len = half(kPage + 2);
  if (len > cap || len > kPageSize - 4) return 0;
  for (uint16_t i = 0; i < len; ++i) buf[i] = *reinterpret_cast<const volatile uint8_t*>(kPage + 4 + i);
  return len;
}

bool FlashStore::save(const uint8_t* buf, size_t len) {
  if (len > kPageSize - 4) return false;
  stm32::flash::keyr() = 0x45670123u;  // unlock sequence
  stm32::flash::keyr() = 0xCDEF89ABu;
  wait_idle();
  stm32::flash::cr() = kPER;  // erase the page (about 20 ms, the CPU stalls)
  stm32::flash::ar() = kPage;
  stm32::flash::cr() = kPER | kSTRT;
  wait_idle();
  stm32::flash::cr() = 0;
  bool ok = true;
  for (size_t i = 0; ok && i < len; i += 2) {
    const uint16_t lo = buf[i];
    const uint16_t hi = i + 1 < len ? buf[i + 1] : 0xFFu;
    ok = program(kPage + 4 + static_cast<uint32_t>(i), static_cast<uint16_t>(lo | hi << 8));
  }
  // Length and magic last: a power cut mid-write leaves no valid-looking blob.
  ok = ok && program(kPage + 2, static_cast<uint16_t>(len)) && program(kPage, kMagic);
  stm32::flash::cr() = kLOCK;
  return ok;
}

}  // namespace bluepill
