#include "lumavel/bluepill/tsl1401.hpp"

namespace lumavel::bluepill {
namespace {

// SI high, clocked in by a CLK rising edge, SI low again while CLK is high:
// pixel 1 is on AO after this edge.
void start_readout(LineScanPort& port) {
  port.clk(false);
  port.si(true);
  port.settle();  // tsu(SI)
  port.clk(true);
  port.settle();  // th(SI), and AO settles on pixel 1
  port.si(false);
}

}  // namespace

void tsl1401_read(LineScanPort& port, uint8_t* line0, uint8_t* line1) {
  start_readout(port);
  for (int i = 0; i < kTslPixels; ++i) {
    uint16_t a = 0, b = 0;
    port.read_pair(a, b);  // pixel i + 1 is valid while CLK is high
    line0[i] = static_cast<uint8_t>(a >> 4);
    line1[i] = static_cast<uint8_t>(b >> 4);
    port.clk(false);
    port.settle();
    port.clk(true);  // next pixel; the 129th edge ends the read-out
    port.settle();
  }
  port.clk(false);
}

void tsl1401_flush(LineScanPort& port) {
  start_readout(port);
  for (int i = 0; i < kTslPixels; ++i) {
    port.clk(false);
    port.settle();
    port.clk(true);
    port.settle();
  }
  port.clk(false);
}

}  // namespace lumavel::bluepill
