// The TSL1401CL clocking sequence, recorded pin by pin on a fake port and
// checked against the datasheet's timing rules (ams TSL1401CL, figure
// "Timing Waveforms" and the switching characteristics):
//  - SI changes only while CLK is low, except its fall, which must come after
//    the CLK rising edge that clocks it in (hold time) and before the next one;
//  - exactly one SI pulse and 129 CLK rising edges per read-out;
//  - each pixel is converted while CLK is high, after a settle, for both sensors,
//    pixel 1 after the edge that clocks SI in, pixel n after edge n.
#include <CppUTest/TestHarness.h>

#include <cstdint>
#include <vector>

#include "lumavel/bluepill/tsl1401.hpp"

using lumavel::bluepill::kTslPixels;

namespace {

struct Event {
  char what;  // 'S' SI, 'C' CLK, 'w' settle, 'A' conversion
  bool level;
};

struct RecordingPort : lumavel::bluepill::LineScanPort {
  std::vector<Event> log;
  bool si_level = false, clk_level = false;
  int rising = 0;  // CLK rising edges since the SI pulse
  void si(bool h) override {
    si_level = h;
    if (h) rising = 0;
    log.push_back({'S', h});
  }
  void clk(bool h) override {
    if (h && !clk_level) ++rising;
    clk_level = h;
    log.push_back({'C', h});
  }
  void settle() override { log.push_back({'w', false}); }
  // The sensors' AO: pixel number (12-bit, shifted) and its complement.
  void read_pair(uint16_t& a, uint16_t& b) override {
    log.push_back({'A', clk_level});
    a = static_cast<uint16_t>(rising << 4);
    b = static_cast<uint16_t>((255 - rising) << 4);
  }
};

void check_sequence(const std::vector<Event>& log, int expected_conversions) {
  bool si = false, clk = false;
  bool settled_since_si = false, settled_since_clk = false;
  int si_pulses = 0, edges = 0, edges_with_si = 0, conversions = 0;
  int edge_of_si_fall = -1;
  for (const Event& e : log) {
    if (e.what == 'S') {
      if (e.level && !si) {
        CHECK_FALSE_TEXT(clk, "SI rises while CLK is high");
        ++si_pulses;
      }
      if (!e.level && si) {
        CHECK_TRUE_TEXT(clk, "SI falls before the CLK edge that clocks it in");
        edge_of_si_fall = edges;
      }
      si = e.level;
      settled_since_si = false;
    } else if (e.what == 'C') {
      if (e.level && !clk) {
        CHECK_TRUE_TEXT(settled_since_si || !si, "no setup time between SI and CLK");
        ++edges;
        if (si) ++edges_with_si;
      }
      clk = e.level;
      settled_since_clk = false;
    } else if (e.what == 'w') {
      settled_since_si = settled_since_clk = true;
    } else {
      CHECK_TRUE_TEXT(e.level, "conversion while CLK is low");
      CHECK_TRUE_TEXT(settled_since_clk, "conversion without AO settling time after the CLK edge");
      ++conversions;
    }
  }
  CHECK_EQUAL(1, si_pulses);
  CHECK_EQUAL(1, edges_with_si);
  CHECK_EQUAL(1, edge_of_si_fall);
  CHECK_EQUAL(kTslPixels + 1, edges);
  CHECK_FALSE(clk);  // idle low
  CHECK_FALSE(si);
  CHECK_EQUAL(expected_conversions, conversions);
}

}  // namespace

TEST_GROUP(Tsl1401){};

TEST(Tsl1401, ReadOutFollowsTheDatasheetTiming) {
  RecordingPort port;
  uint8_t l0[kTslPixels], l1[kTslPixels];
  lumavel::bluepill::tsl1401_read(port, l0, l1);
  check_sequence(port.log, kTslPixels);
}

TEST(Tsl1401, PixelsLandInOrderForBothSensors) {
  RecordingPort port;
  uint8_t l0[kTslPixels], l1[kTslPixels];
  lumavel::bluepill::tsl1401_read(port, l0, l1);
  for (int i = 0; i < kTslPixels; ++i) {
    CHECK_EQUAL(i + 1, l0[i]);  // pixel i + 1 follows edge i + 1
    CHECK_EQUAL(255 - (i + 1), l1[i]);
  }
}

TEST(Tsl1401, FlushClocksAReadOutWithoutConverting) {
  RecordingPort port;
  lumavel::bluepill::tsl1401_flush(port);
  check_sequence(port.log, 0);
}
