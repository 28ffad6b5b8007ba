#include "sink.hpp"

#include "csv.hpp"

namespace lumavel::read {

namespace proto = lumavel::protocol;
using Clock = std::chrono::steady_clock;

Sink::Sink(std::FILE* csv, bool live, bool from_file) : csv_(csv), live_(live), from_file_(from_file) {
  if (csv_ != nullptr) std::fprintf(csv_, "%s\n", csv_header().c_str());
}

Sink::~Sink() { finish(); }

void Sink::finish() {
  if (csv_ != nullptr) std::fflush(csv_);
  csv_ = nullptr;  // once: the file may be closed after this
  if (live_) {
    std::fputc('\n', stdout);
    live_ = false;
  }
}

bool Sink::take(const uint8_t* buf, size_t len, const std::string& where) {
  if (len == 0) return false;
  if (buf[0] == proto::kReportFeatureChunk) {
    // On a live link, a late mailbox reply: not data. A report file holds
    // the measurements its run sent and nothing else (nobody asks through a
    // file): there it is a damaged record (was: skipped unsaid, exit 0, the
    // measurement it replaced missing from the CSV).
    if (!from_file_) return false;
    ++malformed_;
    std::fprintf(stderr, "malformed report %s (id 0x%02x, %zu bytes): a mailbox reply, which a report file never "
                         "holds (its run writes measurements only): a damaged record\n",
                 where.c_str(), buf[0], len);
    return false;
  }
  // The file link writes each measurement as one record of exactly its size;
  // a longer record is a damaged length byte, its tail the records after it
  // (was: decoded from its first bytes, the swallowed last record missing
  // from the CSV, exit 0). A live link may pad a report: not checked there.
  if (from_file_ && len > proto::kMeasurementSize) {
    ++malformed_;
    std::fprintf(stderr, "malformed report %s (id 0x%02x, %zu bytes): longer than a measurement report (%zu bytes), "
                         "which is all a report file's record holds: a damaged length byte, the records after it "
                         "read as its tail\n",
                 where.c_str(), buf[0], len, proto::kMeasurementSize);
    return false;
  }
  proto::Measurement m{};
  const proto::DecodeResult r = proto::decode_measurement(buf, len, m);
  if (!r.ok()) {
    ++malformed_;
    std::fprintf(stderr, "%smalformed report %s (id 0x%02x, %zu bytes): %s%s%s\n",
                 live_ ? "\n" : "", where.c_str(), buf[0], len, proto::to_string(r.error),
                 *r.field ? ": " : "", r.field);
    return false;
  }
  // A report file holds one run's reports in the order it sent them: each a
  // later frame, its dropped frames counted up (was: a record whose CRC holds
  // but whose t_ns or frame_index goes back written as it was, exit 0). Its
  // seq says it is the next one, or that is said below instead.
  if (from_file_ && have_seq_ && m.seq == next_seq_) {
    const char *field = nullptr, *relation = "not after";
    uint64_t was = 0, is = 0;
    if (m.t_ns <= last_.t_ns) field = "t_ns", was = last_.t_ns, is = m.t_ns;
    else if (m.frame_index <= last_.frame_index) field = "frame_index", was = last_.frame_index, is = m.frame_index;
    else if (m.overruns < last_.overruns) field = "overruns", relation = "below", was = last_.overruns, is = m.overruns;
    if (field != nullptr) {
      ++malformed_;
      std::fprintf(stderr,
                   "malformed report %s: %s %llu is %s the previous report's (%llu): a run's reports go forward, "
                   "one frame after another (its dropped frames counted up): a damaged record\n",
                   where.c_str(), field, static_cast<unsigned long long>(is), relation,
                   static_cast<unsigned long long>(was));
    }
  }
  if (have_seq_ && m.seq != next_seq_) {
    const unsigned gap = static_cast<uint16_t>(m.seq - next_seq_);
    if (gap == 0xFFFFu) {  // the previous report again: not new data
      ++duplicated_;
      std::fprintf(stderr, "%sduplicated report %s: seq %u again, skipped\n", live_ ? "\n" : "", where.c_str(),
                   unsigned{m.seq});
      return false;
    }
    if (gap >= 0x8000u) {  // behind the expected one: not a loss
      if (from_file_) ++malformed_;
      std::fprintf(stderr, "%sseq went back from %u to %u %s (%s)\n", live_ ? "\n" : "",
                   unsigned{static_cast<uint16_t>(next_seq_ - 1)}, unsigned{m.seq}, where.c_str(),
                   from_file_ ? "records out of order: a damaged report file" : "the device restarted, or reports out of order");
    } else {
      lost_ += gap;
      if (from_file_) ++malformed_;
      std::fprintf(stderr, "%slost %u report(s) before seq %u %s (%s)\n", live_ ? "\n" : "", gap, unsigned{m.seq},
                   where.c_str(),
                   from_file_ ? "records missing: a damaged report file, which holds every report its run sent"
                              : "host too slow, or reconnect");
    }
  }
  have_seq_ = true;
  next_seq_ = static_cast<uint16_t>(m.seq + 1);
  last_ = m;
  ++count_;
  if (csv_ != nullptr) std::fprintf(csv_, "%s\n", csv_row(m).c_str());
  if (live_) draw(m);
  return true;
}

void Sink::draw(const proto::Measurement& m) {
  const auto now = Clock::now();
  window_.push_back(now);
  while (!window_.empty() && now - window_.front() > std::chrono::seconds(1)) window_.pop_front();
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  std::fprintf(stdout, "\r%7.1f Hz  V %+9.4f m/s  s %11.4f m  heading %+7.4f rad  %-12s  lost %llu  bad %llu\x1b[K",
               static_cast<double>(window_.size()), v_mps(m), distance_m(m), heading_rad(m),
               status_names(m.status).c_str(), static_cast<unsigned long long>(lost_),
               static_cast<unsigned long long>(malformed_));
  std::fflush(stdout);
}

}  // namespace lumavel::read
