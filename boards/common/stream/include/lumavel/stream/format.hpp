// The compact recorded-stream format read by the stream boards (QEMU through
// semihosting, and the host build of the firmware app), and the report file
// they write. Little-endian, no padding.
//
// Input stream (.lvs):
//   header: "LVS1", u16 width, u16 height            (8 bytes)
//   records, in time order, each a tag byte then:
//     'G'  u64 t_ns, i32 rate_z (RateQ24)            gyro sample
//     'F'  u64 t_ns, width*height bytes cam0, then cam1   stereo frame
//     'S'  u8 report id, u8 length, bytes            host sets a feature report
//     'Q'  u8 report id                              host gets a feature report
//   end of file ends the stream.
//
// Output (.lvr): every report the firmware produced, in order:
//     u8 kind ('I' input report, 'R' feature reply), u8 length, bytes
//   (for a set request the reply is one byte, 1 accepted / 0 refused).
#pragma once
#include <cstdint>

namespace lumavel::stream {

constexpr uint8_t kMagic[4] = {'L', 'V', 'S', '1'};
constexpr uint32_t kHeaderSize = 8;
constexpr uint8_t kTagGyro = 'G';
constexpr uint8_t kTagFrame = 'F';
constexpr uint8_t kTagSetFeature = 'S';
constexpr uint8_t kTagGetFeature = 'Q';
constexpr uint32_t kGyroBodySize = 12;

constexpr uint8_t kKindInput = 'I';
constexpr uint8_t kKindReply = 'R';

}  // namespace lumavel::stream
