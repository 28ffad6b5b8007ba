// The two TSL1401CL on GPIO + ADC1: SI on PA4, CLK on PA5 (shared by both
// sensors), AO of sensor 0 on PA0 (ADC channel 0), of sensor 1 on PA1 (channel 1).
#pragma once
#include <cstdint>

#include "lumavel/bluepill/tsl1401.hpp"

namespace bluepill {

class LineScanAdc final : public lumavel::bluepill::LineScanPort {
 public:
  void init();
  void si(bool high) override;
  void clk(bool high) override;
  void settle() override;
  void read_pair(uint16_t& ao0, uint16_t& ao1) override;
};

}  // namespace bluepill
