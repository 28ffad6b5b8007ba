// The firmware app on an emulated board (QEMU): camera and gyro read a
// recorded stream and the report link writes a report file, both through
// semihosting. The same source for every semihosted board:
//   qemu-system-arm -M mps2-an385 -nographic -monitor none -serial none
//     -semihosting-config enable=on,target=native,arg=lumavel,arg=<in.lvs>,arg=<out.lvr>
//     -kernel lumavel_qemu_app.elf
//   qemu-system-riscv32 -M virt -bios none -nographic -monitor none -serial none
//     -semihosting-config (the same) -kernel lumavel_qemu_app.elf
// Exit status: 0 ok, 1 usage/files, 2 bad stream, 3 unconfigured, 4 write failed.
#include <cstdint>

#include "lumavel/board/semihosting.hpp"
#include "lumavel/board/stack_paint.hpp"
#include "lumavel/board/text.hpp"
#include "lumavel/stream/run_stream.hpp"

namespace {


[[noreturn]] void fail(const char* what, const char* detail) {
  lumavel::board::Text<200> t;
  t << "lumavel_qemu_app: " << what << detail << "\n";
  lumavel::semihost::write_text(t.c_str());
  lumavel::semihost::exit(1);
}

}  // namespace

int main() {
  namespace sh = lumavel::semihost;
  lumavel::board::paint_stack();
  char line[256];
  char* words[4] = {};
  if (!sh::command_line(line, sizeof line) || sh::split_words(line, words, 4) != 3) {
    fail("usage: -semihosting-config ...,arg=lumavel,arg=<in.lvs>,arg=<out.lvr>", "");
  }
  const int in = sh::open(words[1], sh::kModeReadBinary);
  if (in < 0) fail("cannot open for reading: ", words[1]);
  const int out = sh::open(words[2], sh::kModeWriteBinary);
  if (out < 0) fail("cannot open for writing: ", words[2]);

  sh::FileSource src(in);
  sh::FileSink sink(out);
  const lumavel::stream::RunSummary s = lumavel::stream::run_stream(src, sink, lumavel::stream::kStreamBoardName);
  const bool flushed = sink.flush();
  sh::close(out);
  sh::close(in);

  lumavel::board::Text<300> t;
  const auto& c = s.counters;
  t << "frames " << c.frames << ", overruns " << uint32_t{c.overruns} << ", capture errors "
    << c.capture_errors << ", gyro samples " << c.gyro_samples << ", feature requests "
    << c.feature_requests << ", watchdog kicks " << s.watchdog_kicks << ", stack used "
    << lumavel::board::stack_used() << " B\n";
  if (s.outcome == lumavel::stream::RunOutcome::kBadStream) {
    t << words[1] << ": record " << s.record_index << ": " << lumavel::stream::to_string(s.stream_error) << "\n";
  }
  sh::write_text(t.c_str());
  int code = static_cast<int>(s.outcome);
  if (code == 0 && !flushed) code = static_cast<int>(lumavel::stream::RunOutcome::kWriteFailed);
  sh::exit(code);
}
