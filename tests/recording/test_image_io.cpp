#include <png.h>

#include <cstdio>

#include "lumavel/host/image_io.hpp"
#include "recording_fixture.hpp"
// CppUTest last: its leak-detector macros redefine new.
#include "CppUTest/TestHarness.h"

using namespace lumavel::host;
using fixture::error_of;

namespace {

// Writes a PNG of any colour type / depth with libpng directly (the project's
// writer only makes 8-bit grayscale), to check that the reader refuses them.
void write_png_raw(const std::string& path, int w, int h, int depth, int colour_type) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), depth, colour_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_color palette[2] = {{0, 0, 0}, {255, 255, 255}};
  if (colour_type == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, 2);
  png_write_info(png, info);
  std::vector<uint8_t> row(static_cast<size_t>(w) * 8, colour_type == PNG_COLOR_TYPE_PALETTE ? 0 : 0x55);
  for (int y = 0; y < h; ++y) png_write_row(png, row.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
}

std::vector<uint8_t> ramp(int w, int h) {
  std::vector<uint8_t> px(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>((i * 37 + i / 7) & 0xff);
  return px;
}

// The CRC-32 of a PNG chunk over its type and data, bytes [from, to) of
// `bytes`, as the 4 big-endian bytes that follow them.
std::string png_chunk_crc(const std::string& bytes, size_t from, size_t to) {
  uint32_t crc = 0xffffffffu;
  for (size_t i = from; i < to; ++i) {
    crc ^= static_cast<uint8_t>(bytes[i]);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc = ~crc;
  std::string out;
  for (int k = 0; k < 4; ++k) out += static_cast<char>(crc >> (24 - 8 * k));
  return out;
}

}  // namespace

TEST_GROUP(ImageIo) {
  fixture::TempDir dir;
  std::string path(const char* name) { return dir.path() + "/" + name; }
};

TEST(ImageIo, PngRoundTripIsExact) {
  const std::vector<uint8_t> px = ramp(37, 11);
  write_png_gray(path("a.png"), px.data(), 37, 11);
  const GrayImage img = read_gray_image(path("a.png"));
  LONGS_EQUAL(37, img.width);
  LONGS_EQUAL(11, img.height);
  CHECK(img.px == px);
}

TEST(ImageIo, AnImageOfAnotherSizeThanExpectedIsNotDecoded) {
  const std::vector<uint8_t> px = ramp(41, 30);
  write_png_gray(path("a.png"), px.data(), 41, 30);
  write_pgm(path("a.pgm"), px.data(), 41, 30);
  for (const char* name : {"a.png", "a.pgm"}) {
    const GrayImage other = read_gray_image(path(name), 40, 30);
    LONGS_EQUAL(41, other.width);
    LONGS_EQUAL(30, other.height);
    CHECK(other.px.empty());
    CHECK(read_gray_image(path(name), 41, 30).px == px);
  }
  // A header claiming 16384 x 16384 pixels with a few rows of data: its size,
  // not "corrupt PNG", and nothing allocated for its pixels.
  std::FILE* f = std::fopen(path("big.png").c_str(), "wb");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, 16384, 16384, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
               PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  std::vector<uint8_t> row(16384, 0x55);
  png_write_row(png, row.data());
  png_write_flush(png);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
  const GrayImage big = read_gray_image(path("big.png"), 40, 30);
  LONGS_EQUAL(16384, big.width);
  CHECK(big.px.empty());
  STRCMP_CONTAINS("corrupt PNG", error_of([&] { read_gray_image(path("big.png")); }).c_str());
}

TEST(ImageIo, PgmRoundTripIsExact) {
  const std::vector<uint8_t> px = ramp(640, 3);
  write_pgm(path("a.pgm"), px.data(), 640, 3);
  const GrayImage img = read_gray_image(path("a.pgm"));
  LONGS_EQUAL(640, img.width);
  LONGS_EQUAL(3, img.height);
  CHECK(img.px == px);
}

TEST(ImageIo, PgmHeaderCommentsAreSkipped) {
  fixture::write_text(path("c.pgm"), std::string("P5\n# made by hand\n3 # width\n1\n255\n") + "abc");
  const GrayImage img = read_gray_image(path("c.pgm"));
  LONGS_EQUAL(3, img.width);
  LONGS_EQUAL('b', img.px[1]);
}

TEST(ImageIo, FormatIsChosenBySignatureNotName) {
  const std::vector<uint8_t> px = ramp(4, 4);
  write_pgm(path("really_pgm.png"), px.data(), 4, 4);
  CHECK(read_gray_image(path("really_pgm.png")).px == px);
}

// A frame's name is a table's field: shown as one (was: an escape sequence
// in a data.csv or images.txt name went to the terminal with the refusal).
TEST(ImageIo, TheNameOfARefusedImageIsShownLikeAField) {
  fixture::write_text(path("a\x1b[2Jb.png"), "junk");
  STRCMP_CONTAINS((dir.path() + "/a\\x1B[2Jb.png: not a PNG or binary PGM file").c_str(),
                  error_of([&] { read_gray_image(path("a\x1b[2Jb.png")); }).c_str());
  STRCMP_CONTAINS((dir.path() + "/c\\x1B[2Jd.png: does not exist").c_str(),
                  error_of([&] { read_gray_image(path("c\x1b[2Jd.png")); }).c_str());
}

TEST(ImageIo, ColourPngIsRefusedNamingTheFile) {
  write_png_raw(path("rgb.png"), 4, 4, 8, PNG_COLOR_TYPE_RGB);
  const std::string e = error_of([&] { read_gray_image(path("rgb.png")); });
  STRCMP_CONTAINS(path("rgb.png").c_str(), e.c_str());
  STRCMP_CONTAINS("not a grayscale image", e.c_str());
}

TEST(ImageIo, PaletteAndAlphaPngAreRefused) {
  write_png_raw(path("pal.png"), 4, 4, 8, PNG_COLOR_TYPE_PALETTE);
  write_png_raw(path("ga.png"), 4, 4, 8, PNG_COLOR_TYPE_GRAY_ALPHA);
  STRCMP_CONTAINS("palette", error_of([&] { read_gray_image(path("pal.png")); }).c_str());
  STRCMP_CONTAINS("alpha", error_of([&] { read_gray_image(path("ga.png")); }).c_str());
}

TEST(ImageIo, SixteenBitAndSubBytePngAreRefused) {
  write_png_raw(path("g16.png"), 4, 4, 16, PNG_COLOR_TYPE_GRAY);
  write_png_raw(path("g4.png"), 4, 4, 4, PNG_COLOR_TYPE_GRAY);
  const std::string e16 = error_of([&] { read_gray_image(path("g16.png")); });
  STRCMP_CONTAINS(path("g16.png").c_str(), e16.c_str());
  STRCMP_CONTAINS("16-bit", e16.c_str());
  STRCMP_CONTAINS("4-bit", error_of([&] { read_gray_image(path("g4.png")); }).c_str());
}

TEST(ImageIo, TruncatedPngIsRefused) {
  const std::vector<uint8_t> px = ramp(40, 30);
  write_png_gray(path("t.png"), px.data(), 40, 30);
  const std::string full = fixture::read_text(path("t.png"));
  for (size_t keep : {full.size() - 1, full.size() - 12, full.size() / 2, size_t{20}, size_t{8}}) {
    fixture::write_text(path("t.png"), full.substr(0, keep));
    const std::string e = error_of([&] { read_gray_image(path("t.png")); });
    STRCMP_CONTAINS(path("t.png").c_str(), e.c_str());
    STRCMP_CONTAINS("corrupt PNG", e.c_str());
  }
}

TEST(ImageIo, CorruptPngIsRefused) {
  const std::vector<uint8_t> px = ramp(40, 30);
  write_png_gray(path("k.png"), px.data(), 40, 30);
  std::string bytes = fixture::read_text(path("k.png"));
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);  // inside IDAT: CRC/zlib error
  fixture::write_text(path("k.png"), bytes);
  const std::string e = error_of([&] { read_gray_image(path("k.png")); });
  STRCMP_CONTAINS(path("k.png").c_str(), e.c_str());
  STRCMP_CONTAINS("corrupt PNG", e.c_str());
}

// A header that claims fewer rows than the data holds, its CRC made right
// (was: read, the extra rows dropped with a warning nobody saw).
TEST(ImageIo, PngWithMoreDataThanItsHeaderSaysIsRefused) {
  const std::vector<uint8_t> px = ramp(40, 31);
  write_png_gray(path("m.png"), px.data(), 40, 31);
  std::string bytes = fixture::read_text(path("m.png"));
  bytes[23] = 30;  // IHDR height (big-endian, bytes 20..23): 31 -> 30
  bytes.replace(29, 4, png_chunk_crc(bytes, 12, 29));  // the IHDR chunk's CRC-32, over its type and data
  fixture::write_text(path("m.png"), bytes);
  const std::string e = error_of([&] { read_gray_image(path("m.png")); });
  STRCMP_CONTAINS(path("m.png").c_str(), e.c_str());
  STRCMP_CONTAINS("corrupt PNG: IDAT: Too much image data", e.c_str());
}

// An ancillary chunk libpng reports as a benign error (here a second pHYs,
// "duplicate"; in the wild a colour profile known to be wrong) does not
// touch the pixels: the frame is read as it is.
TEST(ImageIo, APngWithABadAncillaryChunkIsRead) {
  const std::vector<uint8_t> px = ramp(40, 30);
  write_png_gray(path("a.png"), px.data(), 40, 30);
  std::string bytes = fixture::read_text(path("a.png"));
  // after the signature (8 bytes) and IHDR (4 + 4 + 13 + 4), twice: length 9, "pHYs", 1 x 1 per unit, its CRC-32
  std::string phys("\0\0\0\x09pHYs\0\0\0\1\0\0\0\1\0", 17);
  phys += png_chunk_crc(phys, 4, phys.size());
  bytes.insert(33, phys + phys);
  fixture::write_text(path("a.png"), bytes);
  const GrayImage img = read_gray_image(path("a.png"));
  CHECK(img.px == px);
}

TEST(ImageIo, BadPgmFilesAreRefused) {
  fixture::write_text(path("short.pgm"), "P5\n4 4\n255\n0123456789");
  STRCMP_CONTAINS("truncated PGM: 10 of 16", error_of([&] { read_gray_image(path("short.pgm")); }).c_str());
  fixture::write_text(path("deep.pgm"), "P5\n2 1\n65535\n0123");
  STRCMP_CONTAINS("maxval 65535", error_of([&] { read_gray_image(path("deep.pgm")); }).c_str());
  fixture::write_text(path("ascii.pgm"), "P2\n2 1\n255\n0 1\n");
  STRCMP_CONTAINS("P2", error_of([&] { read_gray_image(path("ascii.pgm")); }).c_str());
  fixture::write_text(path("hdr.pgm"), "P5\nfour 4\n255\n");
  STRCMP_CONTAINS("corrupt PGM header: no width (a decimal number) where it belongs",
                  error_of([&] { read_gray_image(path("hdr.pgm")); }).c_str());
  // The header's values and rules are said (was "corrupt PGM header" or
  // "PGM size out of range", naming nothing).
  fixture::write_text(path("wide.pgm"), "P5\n20000 60\n255\n");
  STRCMP_CONTAINS("PGM header: 20000x60 pixels: each side must be 1..16384",
                  error_of([&] { read_gray_image(path("wide.pgm")); }).c_str());
  fixture::write_text(path("huge.pgm"), "P5\n40 2000000\n255\n");
  STRCMP_CONTAINS("corrupt PGM header: the height is beyond 1000000",
                  error_of([&] { read_gray_image(path("huge.pgm")); }).c_str());
  fixture::write_text(path("glued.pgm"), "P5\n2 1\n255ab");
  STRCMP_CONTAINS("corrupt PGM header: no whitespace byte after maxval 255, before the raster",
                  error_of([&] { read_gray_image(path("glued.pgm")); }).c_str());
  fixture::write_text(path("long.pgm"), "P5\n2 1\n255\nabc");
  STRCMP_CONTAINS("after the raster", error_of([&] { read_gray_image(path("long.pgm")); }).c_str());
  CHECK(error_of([&] { read_gray_image(path("long.pgm")); }).find("CR LF") == std::string::npos);
  // A header written in text mode: CR LF after maxval, one byte too many.
  fixture::write_text(path("crlf.pgm"), "P5\r\n2 1\r\n255\r\nab");
  STRCMP_CONTAINS("PGM has 1 bytes after the raster of its header's 2x1 pixels",
                  error_of([&] { read_gray_image(path("crlf.pgm")); }).c_str());
  STRCMP_CONTAINS("its maxval ends in CR LF", error_of([&] { read_gray_image(path("crlf.pgm")); }).c_str());
  // A comment after maxval is read as pixels (by netpbm too): said as such
  // (was: only 'the header does not describe the image').
  fixture::write_text(path("late.pgm"), "P5\n2 1\n255 # by hand\nab");
  STRCMP_CONTAINS("PGM has 10 bytes after the raster of its header's 2x1 pixels: the header does not describe the image "
                  "(the raster starts with '# by hand': a '#' comment after maxval and its whitespace byte, where the "
                  "format takes none: the raster starts right after that byte, so its 10 bytes are read as pixels; put "
                  "comments before maxval)",
                  error_of([&] { read_gray_image(path("late.pgm")); }).c_str());
}

TEST(ImageIo, OtherFilesAreRefused) {
  fixture::write_text(path("text.png"), "hello");
  fixture::write_text(path("empty.png"), "");
  const std::string e = error_of([&] { read_gray_image(path("text.png")); });
  STRCMP_CONTAINS(path("text.png").c_str(), e.c_str());
  STRCMP_CONTAINS("not a PNG or binary PGM", e.c_str());
  STRCMP_CONTAINS("empty file", error_of([&] { read_gray_image(path("empty.png")); }).c_str());
  STRCMP_CONTAINS("missing.png: does not exist", error_of([&] { read_gray_image(path("missing.png")); }).c_str());
}

TEST(ImageIo, WriterRefusesEmptyImagesAndBadPaths) {
  const uint8_t px[1] = {0};
  STRCMP_CONTAINS("cannot write a 0x1", error_of([&] { write_png_gray(path("z.png"), px, 0, 1); }).c_str());
  STRCMP_CONTAINS("cannot create", error_of([&] { write_png_gray(path("no/such/dir.png"), px, 1, 1); }).c_str());
}

// A full disk gives its reason (was: "write error on close" or "PNG encoder:
// Write Error", no reason, e.g. a render filling its disk).
TEST(ImageIo, WriterSaysTheDiskIsFull) {
  const std::vector<uint8_t> px(640 * 480, 77);
  const char* const full = "No space left on device";
  STRCMP_CONTAINS(full, error_of([&] { write_png_gray("/dev/full", px.data(), 4, 4); }).c_str());  // at fclose
  STRCMP_CONTAINS(full, error_of([&] { write_png_gray("/dev/full", px.data(), 640, 480); }).c_str());  // in libpng
  STRCMP_CONTAINS(full, error_of([&] { write_pgm("/dev/full", px.data(), 640, 480); }).c_str());
}
