// Instruction budget per frame, measured in QEMU: reads a recorded stream
// through semihosting, and times with the board's instruction counter
// (lumavel/board/instruction_counter.hpp; run QEMU with -icount shift=0) the
// phases of each frame:
//   columns  : column_profile of both cameras (the only per-pixel work)
//   kernels  : stereo_measurement (kernel dot products and ratios)
//   observer : the rest of Estimator::step (gyro, observer, status), i.e. step - columns - kernels
//   report   : encode_measurement
// Every timed call is noipa so that no work moves across a counter read.
//   qemu-system-arm -M mps2-an385 -icount shift=0 -nographic -monitor none -serial none
//     -semihosting-config enable=on,target=native,arg=bench,arg=<in.lvs>,arg=<label> -kernel lumavel_qemu_bench.elf
//   qemu-system-riscv32 -M virt -bios none -icount shift=0 ... (the same)
#include <cstdint>

#include "lumavel/app/estimator_config.hpp"
#include "lumavel/board/instruction_counter.hpp"
#include "lumavel/board/semihosting.hpp"
#include "lumavel/board/text.hpp"
#include "lumavel/core/column_profile.hpp"
#include "lumavel/core/estimator.hpp"
#include "lumavel/core/measurement.hpp"
#include "lumavel/protocol/device_config.hpp"
#include "lumavel/protocol/reports.hpp"
#include "lumavel/stream/run_stream.hpp"
#include "lumavel/stream/stream_hal.hpp"

namespace {

namespace counter = lumavel::board::counter;
using counter::ticks_between;

alignas(4) uint8_t frame[2][lumavel::kMaxColumns * lumavel::kMaxRows];  // word loads
lumavel::Estimator estimator;
lumavel::ColumnProfile profile[2];
lumavel::RadialSums radial1;
lumavel::StereoMeasurement measurement;
uint8_t report[lumavel::protocol::kMeasurementSize];

__attribute__((noipa)) void do_columns(uint16_t w, uint16_t h) {
  const lumavel::KernelBank& bank = estimator.bank();
  lumavel::column_profile(frame[0], w, h, w, bank.column_band(), profile[0]);
  lumavel::column_profile(frame[1], w, h, w, bank.column_band(), profile[1], estimator.cam1_rings(), &radial1);
}
__attribute__((noipa)) void do_kernels() {
  lumavel::stereo_measurement(profile[0], profile[1], estimator.bank(), nullptr, measurement);
}
__attribute__((noipa)) lumavel::Estimate do_step(uint64_t t_ns, uint16_t w) {
  return estimator.step(lumavel::FramePair{t_ns, {frame[0], frame[1]}, w});
}
__attribute__((noipa)) void do_report(const lumavel::Estimate& e, uint16_t seq) {
  lumavel::protocol::Measurement m{seq, e.t_ns, e.frame_index, e.v, e.distance, e.heading, e.status, 0, e.gyro_offset};
  lumavel::protocol::encode_measurement(m, report, sizeof report);
}
__attribute__((noipa)) void do_nothing() {}

[[noreturn]] void fail(const char* what) {
  lumavel::semihost::write_text(what);
  lumavel::semihost::exit(1);
}

// "<label> <phase>: <instr/frame> instructions/frame, <x.xx> per stereo pixel"
void print_phase(const char* label, const char* phase, uint64_t ticks, uint32_t frames, uint32_t pixels) {
  const uint64_t instr = ticks * counter::kInstructionsPerTick;
  const uint64_t per_frame = (instr + frames / 2) / frames;
  const uint64_t per_px_x100 = (instr * 100 + uint64_t{frames} * pixels / 2) / (uint64_t{frames} * pixels);
  lumavel::board::Text<160> t;
  t << label << " " << phase << ": " << per_frame << " instructions/frame, " << per_px_x100 / 100 << "."
    << (per_px_x100 % 100 < 10 ? "0" : "") << per_px_x100 % 100 << " per stereo pixel\n";
  lumavel::semihost::write_text(t.c_str());
}


}  // namespace

int main() {
  namespace sh = lumavel::semihost;
  char line[256];
  char* words[4] = {};
  if (!sh::command_line(line, sizeof line) || sh::split_words(line, words, 4) != 3) {
    fail("usage: -semihosting-config ...,arg=bench,arg=<in.lvs>,arg=<label>\n");
  }
  const int in = sh::open(words[1], sh::kModeReadBinary);
  if (in < 0) fail("cannot open the stream\n");
  sh::FileSource src(in);
  lumavel::stream::StreamReader reader(src);
  if (!reader.open()) fail("not a stream\n");
  const uint16_t w = reader.width(), h = reader.height();
  lumavel::EstimatorConfig cfg{};
  if (!lumavel::app::to_estimator_config(lumavel::stream::defaults_for(w, h), cfg) ||
      estimator.configure(cfg) != lumavel::ConfigError::kOk) {
    fail("default configuration refused\n");
  }
  counter::start();

  // Tick rate check: a loop of 2 * 100000 instructions (5000 ticks of the MPS2 SysTick).
  uint32_t a = counter::now();
  counter::spin(100000);
  uint32_t b = counter::now();
  lumavel::board::Text<160> t;
  const uint32_t measured = ticks_between(a, b) * counter::kInstructionsPerTick;
  t << words[2] << " calibration: 200000-instruction loop = " << measured << " instructions by the counter\n";
  sh::write_text(t.c_str());
  if (measured + 400 < 200000 || measured > 200000 + 400) {
    fail("the counter does not count instructions: run QEMU with -icount shift=0\n");
  }

  uint64_t sum_cols = 0, sum_kern = 0, sum_step = 0, sum_report = 0, sum_empty = 0;
  uint32_t frames = 0;
  uint64_t t_ns = 0;
  lumavel::hal::GyroSample g{};
  bool have_gyro = false;
  uint64_t last_gyro = 0;
  while (reader.next_frame(t_ns, frame[0], frame[1])) {
    while ((!have_gyro || last_gyro < t_ns) && reader.next_gyro(g)) {  // as the app does
      estimator.push_gyro(g.t_ns, g.rate_z);
      have_gyro = true;
      last_gyro = g.t_ns;
    }
    const uint32_t t0 = counter::now();
    do_columns(w, h);
    const uint32_t t1 = counter::now();
    do_kernels();
    const uint32_t t2 = counter::now();
    const lumavel::Estimate e = do_step(t_ns, w);
    const uint32_t t3 = counter::now();
    do_report(e, static_cast<uint16_t>(frames));
    const uint32_t t4 = counter::now();
    do_nothing();
    const uint32_t t5 = counter::now();
    if (e.frame_index == 0) continue;  // the first frame has no interval to observe
    sum_cols += ticks_between(t0, t1);
    sum_kern += ticks_between(t1, t2);
    sum_step += ticks_between(t2, t3);
    sum_report += ticks_between(t3, t4);
    sum_empty += ticks_between(t4, t5);
    ++frames;
  }
  sh::close(in);
  if (frames == 0 || reader.error() != lumavel::stream::StreamError::kNone) fail("stream too short or bad\n");
  const uint32_t px = 2u * w * h;
  const uint64_t observer = sum_step > sum_cols + sum_kern ? sum_step - sum_cols - sum_kern : 0;
  t.clear();
  t << words[2] << ": " << uint32_t{w} << "x" << uint32_t{h} << ", " << frames << " frames, " << px << " stereo pixels/frame\n";
  sh::write_text(t.c_str());
  print_phase(words[2], "columns ", sum_cols, frames, px);
  print_phase(words[2], "kernels ", sum_kern, frames, px);
  print_phase(words[2], "observer", observer, frames, px);
  print_phase(words[2], "report  ", sum_report, frames, px);
  print_phase(words[2], "step+report", sum_step + sum_report, frames, px);
  print_phase(words[2], "(empty call, timing overhead)", sum_empty, frames, px);
  sh::exit(0);
}
