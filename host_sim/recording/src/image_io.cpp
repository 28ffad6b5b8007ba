// PNG through libpng (classic API, so that colour/16-bit files are refused
// rather than converted); PGM through a small strict parser.
#include "lumavel/host/image_io.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include "lumavel/host/path_check.hpp"

namespace lumavel::host {
namespace {

constexpr int kMaxSide = kMaxImageSide;  // refuses absurd headers before allocating
// The largest file read as an image: twice the pixels of the largest image
// (an uncompressed PNG or a PGM of it is a little over one byte a pixel). A
// bigger file (a video, a disk image under a frame's name) is refused by its
// size, rather than read whole into memory.
constexpr uint64_t kMaxImageFileBytes = uint64_t{2} * kMaxSide * kMaxSide;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// The path is shown through shown_path (recording_error_in): its name is a
// table's field (a data.csv or images.txt row), whose escape sequences went to
// the terminal as they were.
std::vector<uint8_t> read_whole_file(const std::string& path) {
  if (const std::string why = why_not_a_file(path); !why.empty()) throw recording_error_in(path, why);
  FilePtr f(std::fopen(path.c_str(), "rb"));
  if (!f) throw recording_error_in(path, std::string("cannot open image: ") + std::strerror(errno));
  std::vector<uint8_t> bytes;
  const auto too_big = [&](uint64_t n) {
    return recording_error_in(path, "the file is " + std::to_string(n) + " bytes: more than an 8-bit grayscale image of "
                                    "at most " + std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide) +
                                    " pixels takes (at most " + std::to_string(kMaxImageFileBytes) + " bytes are read)");
  };
  if (std::fseek(f.get(), 0, SEEK_END) == 0) {
    const long n = std::ftell(f.get());
    if (n > 0 && static_cast<uint64_t>(n) > kMaxImageFileBytes) throw too_big(static_cast<uint64_t>(n));
    if (n > 0) bytes.reserve(static_cast<size_t>(n));
    std::fseek(f.get(), 0, SEEK_SET);
  }
  uint8_t buf[65536];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f.get())) > 0) {
    bytes.insert(bytes.end(), buf, buf + got);
    if (bytes.size() > kMaxImageFileBytes) throw too_big(bytes.size());  // grew while read
  }
  if (std::ferror(f.get())) throw recording_error_in(path, "read error");
  return bytes;
}

// ---- PNG decode ------------------------------------------------------------

struct PngSource {
  const uint8_t* data;
  size_t size;
  size_t pos;
  char message[256];
  char damage[256];             // the first warning about the image data itself ("" when none)
  std::vector<png_bytep> rows;  // lives here (address escapes) so it survives longjmp
};

void png_fail(png_structp png, png_const_charp msg) {
  auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
  std::snprintf(src->message, sizeof src->message, "%s", msg);
  png_longjmp(png, 1);
}

void png_quiet_warning(png_structp, png_const_charp) {}

// libpng reads past its "benign" errors with a warning. Those about the
// image data mean a damaged frame: kept, to refuse it; the others
// (ancillary chunks) leave the frame read as it is (png_warning_is_about_pixels).
void png_note_warning(png_structp png, png_const_charp msg) {
  auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
  if (png_warning_is_about_pixels(msg) && !src->damage[0]) std::snprintf(src->damage, sizeof src->damage, "%s", msg);
}

void png_read_mem(png_structp png, png_bytep out, png_size_t n) {
  auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > src->size - src->pos) png_error(png, "truncated file (unexpected end of data)");
  std::memcpy(out, src->data + src->pos, n);
  src->pos += n;
}

// The size a caller expects (0 x 0: any): an image of another size is
// returned with its width and height only, its pixels not decoded.
struct Expect {
  int width = 0, height = 0;
  bool other(long w, long h) const { return width > 0 && (w != width || h != height); }
};

// Returns an empty string on success, the problem otherwise. Only plain data
// lives in this frame across setjmp, as longjmp requires.
std::string decode_png(const uint8_t* data, size_t size, GrayImage& img, Expect expect) {
  // The size in the header (IHDR, the first chunk), read before libpng: an
  // image of another size is answered by it, whatever follows (a header
  // claiming 60000x60000 pixels, a file truncated after its header).
  if (size >= 24 && std::memcmp(data + 12, "IHDR", 4) == 0) {
    const auto be32 = [&](size_t at) {
      return static_cast<long>((uint32_t{data[at]} << 24) | (uint32_t{data[at + 1]} << 16) |
                               (uint32_t{data[at + 2]} << 8) | uint32_t{data[at + 3]});
    };
    const long w = be32(16), h = be32(20);
    if (w >= 1 && h >= 1 && w <= 0x7fffffff && h <= 0x7fffffff && expect.other(w, h)) {
      img.width = static_cast<int>(w);
      img.height = static_cast<int>(h);
      return {};
    }
  }
  PngSource src{data, size, 0, {0}, {0}, {}};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, png_fail, png_note_warning);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return "out of memory";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return std::string("corrupt PNG: ") + src.message;
  }
  png_set_user_limits(png, kMaxSide, kMaxSide);
  // zlib's Adler-32 stays checked: a chunk CRC recomputed over damaged data
  // (an editor, a faulty writer) covers nothing, and only the Adler-32 of the
  // pixels then tells. It costs about 2 % of a 640x480 `run` (docs/benchmarks.md).
  png_set_read_fn(png, &src, png_read_mem);
  png_read_info(png, info);
  const png_uint_32 w = png_get_image_width(png, info);
  const png_uint_32 h = png_get_image_height(png, info);
  const int depth = png_get_bit_depth(png, info);
  const int type = png_get_color_type(png, info);
  char problem[256] = {0};
  if (type != PNG_COLOR_TYPE_GRAY) {
    std::snprintf(problem, sizeof problem, "not a grayscale image (PNG colour type %d%s)", type,
                  type == PNG_COLOR_TYPE_PALETTE ? ", palette"
                  : (type & PNG_COLOR_MASK_COLOR) ? ", colour"
                                                   : ", with alpha");
  } else if (depth != 8) {
    std::snprintf(problem, sizeof problem, "wrong depth: %d-bit grayscale, need 8-bit", depth);
  }
  if (problem[0]) {
    png_destroy_read_struct(&png, &info, nullptr);
    return problem;
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  img.px.resize(static_cast<size_t>(w) * h);
  src.rows.resize(h);
  for (png_uint_32 y = 0; y < h; ++y) src.rows[y] = img.px.data() + static_cast<size_t>(y) * w;
  png_read_image(png, src.rows.data());
  png_read_end(png, nullptr);  // checks the trailing chunks: catches truncation after IDAT
  png_destroy_read_struct(&png, &info, nullptr);
  if (src.damage[0]) return std::string("corrupt PNG: ") + src.damage;
  return {};
}

// ---- PGM decode ------------------------------------------------------------

// Reads one header integer, skipping whitespace and '#' comments. -1: no
// number where one belongs; -2: one beyond 10^6 (no side or maxval is).
long pgm_int(const uint8_t* d, size_t n, size_t& pos) {
  for (;;) {
    while (pos < n && (d[pos] == ' ' || d[pos] == '\t' || d[pos] == '\r' || d[pos] == '\n')) ++pos;
    if (pos < n && d[pos] == '#') {
      while (pos < n && d[pos] != '\n') ++pos;
      continue;
    }
    break;
  }
  if (pos >= n || d[pos] < '0' || d[pos] > '9') return -1;
  long value = 0;
  while (pos < n && d[pos] >= '0' && d[pos] <= '9') {
    value = value * 10 + (d[pos] - '0');
    if (value > 1000000) return -2;
    ++pos;
  }
  return value;
}

std::string decode_pgm(const uint8_t* d, size_t n, GrayImage& img, Expect expect) {
  // What is wrong in the header is said with its value and the rule (was
  // "corrupt PGM header" or "PGM size out of range", nothing more).
  size_t pos = 2;
  const char* const names[3] = {"width", "height", "maxval"};
  long v[3] = {};
  for (int i = 0; i < 3; ++i) {
    v[i] = pgm_int(d, n, pos);
    if (v[i] == -1) return std::string("corrupt PGM header: no ") + names[i] + " (a decimal number) where it belongs";
    if (v[i] == -2) return std::string("corrupt PGM header: the ") + names[i] + " is beyond 1000000";
  }
  const long w = v[0], h = v[1], maxval = v[2];
  if (pos >= n || !(d[pos] == ' ' || d[pos] == '\t' || d[pos] == '\r' || d[pos] == '\n'))
    return "corrupt PGM header: no whitespace byte after maxval " + std::to_string(maxval) + ", before the raster";
  ++pos;  // exactly one whitespace byte before the raster
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide)
    return "PGM header: " + std::to_string(w) + "x" + std::to_string(h) + " pixels: each side must be 1.." +
           std::to_string(kMaxSide);
  if (maxval != 255) return "wrong depth: PGM maxval " + std::to_string(maxval) + ", need 255 (8-bit)";
  if (expect.other(w, h)) {
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    return {};
  }
  const size_t need = static_cast<size_t>(w) * static_cast<size_t>(h);
  if (n - pos < need)
    return "truncated PGM: " + std::to_string(n - pos) + " of " + std::to_string(need) + " pixel bytes";
  if (n - pos > need) {
    // A CR LF after maxval (a header written in text mode) leaves exactly one.
    const bool crlf = n - pos - need == 1 && d[pos - 1] == '\r' && d[pos] == '\n';
    // A '#' comment after maxval's whitespace byte is read as pixels (by
    // netpbm too): its length is the excess (was: only 'the header does not
    // describe the image', which it does).
    const bool comment = d[pos] == '#';
    size_t comment_end = pos;
    while (comment && comment_end < n && d[comment_end] != '\n') ++comment_end;
    return "PGM has " + std::to_string(n - pos - need) + " bytes after the raster of its header's " + std::to_string(w) +
           "x" + std::to_string(h) + " pixels: the header does not describe the image" +
           (crlf ? " (its maxval ends in CR LF, two bytes where the format takes one: a header written in text mode?)"
            : comment
                ? " (the raster starts with '" + shown_text(std::string(d + pos, d + std::min(comment_end, pos + 40))) +
                      "': a '#' comment after maxval and its whitespace byte, where the format takes none: the raster "
                      "starts right after that byte, so its " + std::to_string(std::min(comment_end + 1, n) - pos) +
                      " bytes are read as pixels; put comments before maxval)"
                : "");
  }
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  img.px.assign(d + pos, d + pos + need);
  return {};
}

// ---- writers ----------------------------------------------------------------

struct PngSink {
  char message[256];
};

void png_sink_fail(png_structp png, png_const_charp msg) {
  auto* s = static_cast<PngSink*>(png_get_error_ptr(png));
  std::snprintf(s->message, sizeof s->message, "%s", msg);
  png_longjmp(png, 1);
}

std::string encode_png(std::FILE* f, const uint8_t* px, int w, int h) {
  PngSink sink{{0}};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, png_sink_fail, png_quiet_warning);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return "out of memory";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return std::string("PNG encoder: ") + sink.message;
  }
  png_init_io(png, f);
  png_set_compression_level(png, 1);
  // "Up" suits sideways views (texture varies along u, little along v): smaller
  // files, and no slower to decode than "Sub" or no filter (measured on renders).
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  for (int y = 0; y < h; ++y) png_write_row(png, px + static_cast<size_t>(y) * static_cast<size_t>(w));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return {};
}

void check_size(const std::string& path, int w, int h) {
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide)
    throw recording_error_in(path, "cannot write a " + std::to_string(w) + "x" + std::to_string(h) + " image");
}

}  // namespace

namespace {

GrayImage decode(const uint8_t* data, size_t size, const std::string& name, Expect expect) {
  GrayImage img;
  std::string problem;
  static const uint8_t kPngSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size >= 8 && std::memcmp(data, kPngSig, 8) == 0) {
    problem = decode_png(data, size, img, expect);
  } else if (size >= 2 && data[0] == 'P' && data[1] == '5') {
    problem = decode_pgm(data, size, img, expect);
  } else if (size >= 2 && data[0] == 'P' && data[1] >= '1' && data[1] <= '7') {
    problem = std::string("unsupported netpbm type P") + static_cast<char>(data[1]) +
              " (need binary PGM, P5)";
  } else if (size == 0) {
    problem = "empty file";
  } else {
    problem = "not a PNG or binary PGM file";
  }
  if (!problem.empty()) throw recording_error_in(name, problem);
  return img;
}

}  // namespace

bool png_warning_is_about_pixels(const char* message) {
  return std::strstr(message, "IDAT") != nullptr || std::strstr(message, "image data") != nullptr ||
         std::strstr(message, "compressed data") != nullptr;
}

GrayImage decode_gray_image(const uint8_t* data, size_t size, const std::string& name) {
  return decode(data, size, name, Expect{});
}

GrayImage read_gray_image(const std::string& path) {
  const std::vector<uint8_t> bytes = read_whole_file(path);
  return decode(bytes.data(), bytes.size(), path, Expect{});
}

GrayImage read_gray_image(const std::string& path, int expect_width, int expect_height) {
  const std::vector<uint8_t> bytes = read_whole_file(path);
  return decode(bytes.data(), bytes.size(), path, Expect{expect_width, expect_height});
}

namespace {

// `what` and the system's reason (errno, cleared before the write): a full
// disk says "No space left on device" (was: "write error on close", no reason).
std::string with_reason(const std::string& what) {
  return errno != 0 ? what + ": " + std::strerror(errno) : what;
}

}  // namespace

void write_png_gray(const std::string& path, const uint8_t* px, int w, int h) {
  check_size(path, w, h);
  FilePtr f(std::fopen(path.c_str(), "wb"));
  if (!f) throw recording_error_in(path, std::string("cannot create: ") + std::strerror(errno));
  errno = 0;
  const std::string problem = encode_png(f.get(), px, w, h);
  if (!problem.empty()) throw recording_error_in(path, with_reason(problem));
  if (std::fclose(f.release()) != 0) throw recording_error_in(path, with_reason("write error on close"));
}

void write_pgm(const std::string& path, const uint8_t* px, int w, int h) {
  check_size(path, w, h);
  FilePtr f(std::fopen(path.c_str(), "wb"));
  if (!f) throw recording_error_in(path, std::string("cannot create: ") + std::strerror(errno));
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  errno = 0;
  const bool ok = std::fprintf(f.get(), "P5\n%d %d\n255\n", w, h) > 0 && std::fwrite(px, 1, n, f.get()) == n;
  if (!ok || std::fclose(f.release()) != 0) throw recording_error_in(path, with_reason("write error"));
}

}  // namespace lumavel::host
