// TSL1401CL line-scan read-out (ams datasheet, "Timing Waveforms"): a serial
// input (SI) pulse clocked in by a CLK rising edge starts the read-out of the
// 128 pixels (and a new integration); each following CLK rising edge puts the
// next pixel on AO; the 129th edge ends the read-out (AO goes high-Z).
// Both sensors share SI and CLK, so they integrate over the same interval.
// Pin and ADC access go through LineScanPort so that the sequence runs, and
// is tested, on the host.
#pragma once
#include <cstdint>

namespace lumavel::bluepill {

constexpr int kTslPixels = 128;

class LineScanPort {
 public:
  virtual void si(bool high) = 0;
  virtual void clk(bool high) = 0;
  // At least the datasheet's setup/hold/settling time (tsu(SI) 20 ns, th(SI) 0,
  // ts AO settling 120 ns): a few cycles on the target.
  virtual void settle() = 0;
  // Converts AO of sensor 0 and sensor 1 (12-bit).
  virtual void read_pair(uint16_t& ao0, uint16_t& ao1) = 0;

 protected:
  ~LineScanPort() = default;
};

// Reads one line from each sensor (pixel 1 first) into 8-bit buffers and
// starts the next integration. 12-bit samples keep their top 8 bits.
void tsl1401_read(LineScanPort& port, uint8_t* line0, uint8_t* line1);
// Clocks a read-out without converting: discards stale charge and starts a
// clean integration (after power-up or an exposure change).
void tsl1401_flush(LineScanPort& port);

}  // namespace lumavel::bluepill
