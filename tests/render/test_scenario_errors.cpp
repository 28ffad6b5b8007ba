// Scenario parsing: a bad key or value is refused with FILE:LINE and the key.
#include <CppUTest/TestHarness.h>
#include <CppUTest/MemoryLeakWarningPlugin.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>

#include <string>
#include <vector>

#include "lumavel/host/image_io.hpp"
#include "lumavel/host/render/scenario_loader.hpp"
#include "lumavel/host/render/surface_pattern.hpp"

using namespace lumavel::host::render;

namespace {

const char* const kGood =
    "duration_s: 2\n"                                      // 1
    "camera:\n"                                            // 2
    "  resolution: [40, 30]\n"                             // 3
    "  rate_hz: 60\n"                                      // 4
    "trajectory:\n"                                        // 5
    "  segments:\n"                                        // 6
    "    - {type: straight, duration_s: 2, speed: 0.5}\n"  // 7
    "scene:\n"                                             // 8
    "  planes:\n"                                          // 9
    "    - from: [0, 2]\n"                                 // 10
    "      to: [5, 2]\n"                                   // 11
    "      z: [-1, 1]\n"                                   // 12
    "      pattern: {type: uniform, value: 90}\n";         // 13

std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "bad.yaml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  s.replace(s.find(from), from.size(), to);
  return s;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// What load_photo_gray says of `photo` ("(read)" if it reads it); the photo
// and its folder are removed after.
std::string photo_error(const std::string& photo, const char* dir) {
  std::string e = "(read)";
  try {
    int w = 0, h = 0;
    load_photo_gray(photo, w, h);
  } catch (const std::runtime_error& x) {
    e = x.what();
  }
  std::remove(photo.c_str());
  rmdir(dir);
  return e;
}

}  // namespace

// yaml-cpp builds its scanner's static patterns on first use (a '-', say):
// not leaks of the code under test, whichever test comes first.
TEST_GROUP(ScenarioErrors) {
  void setup() override { MemoryLeakWarningPlugin::saveAndDisableNewDeleteOverloads(); }
  void teardown() override { MemoryLeakWarningPlugin::restoreNewDeleteOverloads(); }
};

TEST(ScenarioErrors, GoodScenarioParses) {
  const Scenario s = parse_scenario(kGood, "good.yaml");
  CHECK_EQUAL(40, s.camera.width);
  CHECK_EQUAL(1u, s.planes.size());
  DOUBLES_EQUAL(90, s.planes[0].pattern.value, 0);
}

TEST(ScenarioErrors, UnknownKeyNamesFileLineAndKey) {
  const std::string e = error_of(replace(kGood, "  rate_hz: 60", "  rate_hzz: 60"));
  STRCMP_CONTAINS("bad.yaml:4:", e.c_str());
  STRCMP_CONTAINS("rate_hzz", e.c_str());
}

TEST(ScenarioErrors, OutOfRangeValue) {
  const std::string e = error_of(replace(kGood, "rate_hz: 60", "rate_hz: -5"));
  STRCMP_CONTAINS("bad.yaml:4:", e.c_str());
  STRCMP_CONTAINS("rate_hz", e.c_str());
}

// More pixels than lumavel bins a frame of (was: rendered, 45 min at 8192x8192,
// then refused by run's check); 4096x4096 is the most.
TEST(ScenarioErrors, ResolutionBeyondWhatRunBins) {
  const std::string e = error_of(replace(kGood, "resolution: [40, 30]", "resolution: [8192, 8192]"));
  STRCMP_CONTAINS("bad.yaml:3: 'resolution' = [8192, 8192] is 67108864 pixels: lumavel bins frames of at most "
                  "16777216 pixels (4096x4096", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, "resolution: [40, 30]", "resolution: [4096, 4096]")).c_str());
  STRCMP_CONTAINS("'resolution' = [4097, 4096] is 16781312 pixels",
                  error_of(replace(kGood, "resolution: [40, 30]", "resolution: [4097, 4096]")).c_str());
}

TEST(ScenarioErrors, NotANumber) {
  const std::string e = error_of(replace(kGood, "value: 90", "value: grey"));
  STRCMP_CONTAINS("bad.yaml:13:", e.c_str());
  STRCMP_CONTAINS("'value' must be a number", e.c_str());
  // A number beyond a double's range is one (was: ''value' must be a number, got '1e400'').
  STRCMP_CONTAINS("bad.yaml:13: 'value' = '1e400' is beyond the largest number (about 1.8e308)",
                  error_of(replace(kGood, "value: 90", "value: 1e400")).c_str());
  // One too small for a double, the same (was: ''value' = 0 is out of range').
  STRCMP_CONTAINS("bad.yaml:13: 'value' = '1e-400' is nearer 0 than the smallest number (about 2.2e-308)",
                  error_of(replace(kGood, "value: 90", "value: 1e-400")).c_str());
}

TEST(ScenarioErrors, WrongListLength) {
  const std::string e = error_of(replace(kGood, "resolution: [40, 30]", "resolution: [40]"));
  STRCMP_CONTAINS("bad.yaml:3:", e.c_str());
  STRCMP_CONTAINS("resolution", e.c_str());
}

TEST(ScenarioErrors, UnknownWord) {
  const std::string e = error_of(replace(kGood, "type: straight", "type: spiral"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("spiral", e.c_str());
}

// A YAML escape ("left\0x", "\e[2J") went into the message as it was: cut
// short at the NUL (was: "'look' = 'left"), an escape sequence sent to the
// terminal; a 1 MB word went out whole.
TEST(ScenarioErrors, ValuesInMessagesAreShownLikeFields) {
  STRCMP_EQUAL("bad.yaml:7: 'type' = 'spi\\x00ral\\x1B[2J' is not one of: straight, arc",
               error_of(replace(kGood, "type: straight", "type: \"spi\\0ral\\e[2J\"")).c_str());
  const std::string e = error_of(replace(kGood, "type: straight", "type: " + std::string(300000, 's')));
  STRCMP_CONTAINS("(300000 characters)' is not one of: straight, arc", e.c_str());
  CHECK(e.size() < 600);
}

TEST(ScenarioErrors, ArcNeedsRadiusAndTurn) {
  const std::string e = error_of(replace(kGood, "type: straight", "type: arc"));
  STRCMP_CONTAINS("bad.yaml:7:", e.c_str());
  STRCMP_CONTAINS("radius_m", e.c_str());
}

TEST(ScenarioErrors, MissingPhotoFile) {
  const std::string e =
      error_of(replace(kGood, "{type: uniform, value: 90}", "{type: photo, file: /nonexistent/x.png, size_m: [1, 1]}"));
  STRCMP_CONTAINS("bad.yaml:13:", e.c_str());
  STRCMP_CONTAINS("/nonexistent/x.png", e.c_str());
}

// "p.pgm\0junk" (a YAML escape) named p.pgm to the system (was: that photo
// rendered, exit 0), as a NUL in a recording table's file name is refused.
TEST(ScenarioErrors, APhotoNameWithANulByteIsRefused) {
  char dir[] = "/tmp/lumavel_photo_nul_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string photo = std::string(dir) + "/p.pgm";
  std::FILE* f = std::fopen(photo.c_str(), "wb");
  std::fputs("P5\n2 2\n255\n\x10\x80\x40\xf0", f);
  std::fclose(f);
  const std::string e = error_of(replace(kGood, "{type: uniform, value: 90}",
                                         "{type: photo, file: \"" + photo + "\\0junk\", size_m: [1, 1]}"));
  std::remove(photo.c_str());
  rmdir(dir);
  STRCMP_EQUAL(("bad.yaml:13: photo file name '" + photo + "' is followed by a NUL byte inside the name (character " +
                std::to_string(photo.size() + 1) + "): the system would read the name only up to it")
                   .c_str(),
               e.c_str());
}

// A photo PGM whose header says fewer pixels than it holds (64x32 over a
// 64x64 picture) rendered the top half as the whole photo, exit 0: refused
// as a recording's frame is, with the count and the header's size.
TEST(ScenarioErrors, APhotoPgmWithBytesAfterItsRasterIsRefused) {
  char dir[] = "/tmp/lumavel_photo_long_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string photo = std::string(dir) + "/p.pgm";
  std::FILE* f = std::fopen(photo.c_str(), "wb");
  std::fputs("P5\n2 1\n255\n\x10\x80\x40\xf0", f);
  std::fclose(f);
  const std::string e = photo_error(photo, dir);
  STRCMP_EQUAL((photo + ": PGM has 2 bytes after the raster of its header's 2x1 pixels: the header does not "
                "describe the image").c_str(),
               e.c_str());
}

// A photo PNG whose header says fewer rows than its data holds (31 rows
// under a header of 30), or with bytes after its zlib stream: libpng's
// simplified API read on with a warning nobody saw, and the photo was
// rendered from what the header says, exit 0. Refused as a recording's frame
// is ("corrupt PNG: IDAT: Too much image data").
TEST(ScenarioErrors, APhotoPngWithMoreDataThanItsHeaderSaysIsRefused) {
  char dir[] = "/tmp/lumavel_photo_png_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string photo = std::string(dir) + "/p.png";
  std::vector<uint8_t> px(40 * 31);
  for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>((i * 37 + i / 7) & 0xff);
  lumavel::host::write_png_gray(photo, px.data(), 40, 31);
  std::string bytes;
  {
    std::FILE* f = std::fopen(photo.c_str(), "rb");
    char b[4096];
    size_t n;
    while ((n = std::fread(b, 1, sizeof b, f)) > 0) bytes.append(b, n);
    std::fclose(f);
  }
  bytes[23] = 30;  // IHDR height (big-endian, bytes 20..23): 31 -> 30, and the chunk's CRC-32 (bytes 29..32) made right
  const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(bytes.data() + 12), 17);
  for (int k = 0; k < 4; ++k) bytes[static_cast<size_t>(29 + k)] = static_cast<char>(crc >> (24 - 8 * k));
  std::FILE* f = std::fopen(photo.c_str(), "wb");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  const std::string e = photo_error(photo, dir);
  STRCMP_EQUAL((photo + ": corrupt PNG: IDAT: Too much image data").c_str(), e.c_str());
}

namespace {

// A PNG of w x h pixels written by hand (zlib): `rows` is the raw image
// data, each row led by its filter byte (0).
void write_png_by_hand(const std::string& path, int w, int h, int depth, int colour, const std::string& rows) {
  std::vector<Bytef> z(compressBound(rows.size()));
  uLongf zn = z.size();
  CHECK(compress(z.data(), &zn, reinterpret_cast<const Bytef*>(rows.data()), rows.size()) == Z_OK);
  std::string png("\x89PNG\r\n\x1a\n", 8);
  const auto be32 = [](std::string& to, uLong v) {
    for (int k = 0; k < 4; ++k) to += static_cast<char>((v >> (24 - 8 * k)) & 0xff);
  };
  const auto chunk = [&png, &be32](const char* type, const std::string& data) {
    be32(png, data.size());
    const std::string body = std::string(type, 4) + data;
    png += body;
    be32(png, crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
  };
  std::string ihdr;
  be32(ihdr, static_cast<uLong>(w));
  be32(ihdr, static_cast<uLong>(h));
  ihdr += static_cast<char>(depth);
  ihdr += static_cast<char>(colour);
  ihdr += std::string(3, '\0');  // compression, filter, no interlace
  chunk("IHDR", ihdr);
  chunk("IDAT", std::string(reinterpret_cast<const char*>(z.data()), zn));
  chunk("IEND", "");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  std::fwrite(png.data(), 1, png.size(), f);
  std::fclose(f);
}

// A gray + alpha PNG of w x 1 pixels: gray ramp, alpha `alpha` in column
// `at`, 255 elsewhere.
void write_gray_alpha_png(const std::string& path, int w, int at, uint8_t alpha) {
  std::string raw(1, '\0');
  for (int x = 0; x < w; ++x) {
    raw += static_cast<char>(x * 255 / w);
    raw += static_cast<char>(x == at ? alpha : 255);
  }
  write_png_by_hand(path, w, 1, 8, 4, raw);
}

}  // namespace

// A photo with transparent pixels: the simplified API composed them onto
// black when it converted to gray, and the photo was rendered so, exit 0 (a
// fully transparent one as a plain black wall). Refused, where it says; an
// alpha channel that is opaque throughout is read as before.
TEST(ScenarioErrors, APhotoPngWithTransparentPixelsIsRefused) {
  char dir[] = "/tmp/lumavel_photo_alpha_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string photo = std::string(dir) + "/p.png";
  write_gray_alpha_png(photo, 16, 5, 0);
  STRCMP_EQUAL((photo + ": 1 of its 16 pixels are transparent or partly so (the first at column 5, row 0, alpha 0 of "
                "255): a photo paints its plane opaque, and what shows through is not known (it would be read as "
                "composed onto black); flatten it onto a background first").c_str(),
               photo_error(photo, dir).c_str());
  char opaque_dir[] = "/tmp/lumavel_photo_opaque_XXXXXX";
  CHECK(mkdtemp(opaque_dir) != nullptr);
  const std::string opaque = std::string(opaque_dir) + "/p.png";
  write_gray_alpha_png(opaque, 16, 5, 255);
  STRCMP_EQUAL("(read)", photo_error(opaque, opaque_dir).c_str());
}

// A 16-bit gray photo without gAMA or sRGB chunk was read as linear light
// (libpng's simplified API by default) and rendered brighter and flatter than
// its 8-bit twin: levels 0x4040 and 0xC0C0 as 136 and 224, not 64 and 192.
// Read as its 8-bit twin is.
TEST(ScenarioErrors, ASixteenBitPhotoReadsAsItsEightBitTwin) {
  char dir[] = "/tmp/lumavel_photo_16_XXXXXX";
  CHECK(mkdtemp(dir) != nullptr);
  const std::string p8 = std::string(dir) + "/p8.png", p16 = std::string(dir) + "/p16.png";
  std::string raw8(1, '\0'), raw16(1, '\0');
  for (int x = 0; x < 16; ++x) {
    const char level = static_cast<char>(x * 17);
    raw8 += level;
    raw16 += std::string(2, level);  // 0xLL -> 0xLLLL: the same level in 16 bits
  }
  write_png_by_hand(p8, 16, 1, 8, 0, raw8);
  write_png_by_hand(p16, 16, 1, 16, 0, raw16);
  int w8 = 0, h8 = 0, w16 = 0, h16 = 0;
  const std::vector<unsigned char> a = load_photo_gray(p8, w8, h8);
  const std::vector<unsigned char> b = load_photo_gray(p16, w16, h16);
  std::remove(p8.c_str());
  std::remove(p16.c_str());
  rmdir(dir);
  LONGS_EQUAL(16, w16);
  LONGS_EQUAL(16, a.size());
  LONGS_EQUAL(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) LONGS_EQUAL(static_cast<int>(i) * 17, b[i]);
}

// 'dark' is a list of intervals: one interval without its outer brackets
// was refused as "'dark' must be a list of 2 numbers", which it is.
TEST(ScenarioErrors, ADarkIntervalWithoutItsBracketsIsSaidAsSuch) {
  STRCMP_EQUAL("bad.yaml:14: 'dark' must be a list of [start_s, end_s] intervals (e.g. dark: [[3, 3.5]]): an element "
               "is '0.5', not an interval",
               error_of(std::string(kGood) + "lighting: {dark: [0.5, 0.8]}\n").c_str());
  STRCMP_EQUAL("bad.yaml:14: 'dark' must be a list of [start_s, end_s] intervals (e.g. dark: [[3, 3.5]]): an element "
               "is a list of 3 numbers, not 2",
               error_of(std::string(kGood) + "lighting: {dark: [[0.5, 0.8, 1]]}\n").c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string(kGood) + "lighting: {dark: [[0.5, 0.8]]}\n").c_str());
}

// An empty photo name was said as the scenario's folder: "photo 'DIR/' is a
// folder, not a file".
TEST(ScenarioErrors, AnEmptyPhotoNameIsSaidAsSuch) {
  STRCMP_EQUAL("bad.yaml:13: photo 'file' is empty: it names the photo (relative to the scenario file)",
               error_of(replace(kGood, "{type: uniform, value: 90}", "{type: photo, file: \"\", size_m: [1, 1]}")).c_str());
}

TEST(ScenarioErrors, BadPlaneGeometry) {
  STRCMP_CONTAINS("bad.yaml:12:", error_of(replace(kGood, "z: [-1, 1]", "z: [1, -1]")).c_str());
  STRCMP_CONTAINS("bad.yaml:11:", error_of(replace(kGood, "to: [5, 2]", "to: [0, 2]")).c_str());
}

TEST(ScenarioErrors, TooManyPlanes) {
  std::string text = kGood;
  for (int i = 0; i < 256; ++i) text += "    - {from: [0, 3], to: [1, 3], z: [0, 1], pattern: {type: uniform}}\n";
  const std::string e = error_of(text);
  STRCMP_CONTAINS("bad.yaml:10:", e.c_str());
  STRCMP_CONTAINS("at most 256 planes", e.c_str());
}

TEST(ScenarioErrors, MissingRequiredKeys) {
  STRCMP_CONTAINS("duration_s", error_of(replace(kGood, "duration_s: 2\n", "")).c_str());
  CHECK(contains(error_of("duration_s: 2\n"), "trajectory"));
}

TEST(ScenarioErrors, YamlSyntaxErrorNamesTheLine) {
  const std::string e = error_of(replace(kGood, "  resolution: [40, 30]", "  resolution: [40, 30"));
  STRCMP_CONTAINS("bad.yaml:", e.c_str());
  STRCMP_CONTAINS("YAML syntax", e.c_str());
}

// A tab in the indentation: yaml-cpp's words alone did not say why.
TEST(ScenarioErrors, ATabInTheIndentationIsNamed) {
  const std::string e = error_of(replace(kGood, "  rate_hz: 60", "\trate_hz: 60"));
  STRCMP_CONTAINS("bad.yaml:4: YAML syntax: ", e.c_str());
  STRCMP_CONTAINS("; this line is indented with a tab, and YAML indents with spaces only", e.c_str());
  // A tab after the indentation is no indentation.
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, "  rate_hz: 60", "  rate_hz:\t60")).c_str());
}

// yaml-cpp ends lines at LF and CR LF only: CR-only line ends made one long
// line of the file (was: 'bad.yaml:1: YAML syntax: illegal map value', and
// with a first '#' comment line 'empty file'); CR LF is read.
TEST(ScenarioErrors, CarriageReturnOnlyLineEndsAreNamed) {
  std::string cr = kGood, crlf;
  for (char& c : cr)
    if (c == '\n') c = '\r';
  for (const char c : std::string(kGood)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  STRCMP_CONTAINS("bad.yaml:1: a carriage return (CR) inside the line, at character 14: lines must end with LF or CR LF",
                  error_of(cr).c_str());
  STRCMP_CONTAINS("bad.yaml:1: a carriage return (CR) inside the line, at character 13:",
                  error_of("# a scenario\r" + cr).c_str());
  STRCMP_EQUAL("(accepted)", error_of(crlf).c_str());
}

// A NUL byte was taken by yaml-cpp for an escape (was: 'bad.yaml:4: YAML
// syntax: unknown escape character: j').
TEST(ScenarioErrors, ANulByteNamesItsLine) {
  STRCMP_EQUAL("bad.yaml:4: a NUL byte at character 14: a YAML file is text (a binary or damaged file?)",
               error_of(replace(kGood, "  rate_hz: 60", std::string("  rate_hz: 60\0junk", 18))).c_str());
}

TEST(ScenarioErrors, MissingFileIsNamed) {
  try {
    load_scenario("/nonexistent/scenario.yaml");
    FAIL("accepted a missing file");
  } catch (const ScenarioError& e) {
    STRCMP_CONTAINS("/nonexistent/scenario.yaml", e.what());
  }
}

// A scenario path that is not a regular file says what it is; a FIFO is
// never opened (render would wait on it forever); an empty file is empty.
TEST(ScenarioErrors, ScenarioThatIsNotAFileSaysWhatItIs) {
  auto load_error = [](const std::string& path) -> std::string {
    try {
      load_scenario(path);
    } catch (const ScenarioError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  STRCMP_EQUAL("/nonexistent/scenario.yaml: does not exist", load_error("/nonexistent/scenario.yaml").c_str());
  STRCMP_EQUAL("/tmp: is a folder, not a scenario file", load_error("/tmp").c_str());
  STRCMP_EQUAL("/dev/null: is a character device node, not a scenario file", load_error("/dev/null").c_str());
  char fifo[] = "/tmp/lumavel_scenario_fifo_XXXXXX";
  CHECK(mkdtemp(fifo) != nullptr);
  const std::string dir = fifo, path = dir + "/s.yaml";
  CHECK(::mkfifo(path.c_str(), 0600) == 0);
  const std::string e = load_error(path);
  ::unlink(path.c_str());
  ::rmdir(dir.c_str());
  STRCMP_EQUAL((path + ": is a FIFO (named pipe), not a scenario file").c_str(), e.c_str());
  STRCMP_CONTAINS("bad.yaml: empty file", error_of("").c_str());
  // Comments alone are no empty file (was: 'empty file').
  STRCMP_EQUAL("bad.yaml: no key: the file holds only comments: a scenario holds KEY: VALUE lines "
               "(host_sim/scenarios/README.md)",
               error_of("# to do\n").c_str());
  STRCMP_CONTAINS("bad.yaml:1: a scenario must be a YAML map", error_of("- a list").c_str());
}

TEST(ScenarioErrors, OverridesApply) {
  Scenario s = parse_scenario(kGood, "good.yaml");
  Overrides o;
  o.width = 20;
  o.height = 15;
  o.exposure_frames = 1.25;
  o.seed = 99;
  o.duration_s = 1;
  apply_overrides(s, o);
  CHECK_EQUAL(20, s.camera.width);
  CHECK_EQUAL(15, s.camera.height);
  DOUBLES_EQUAL(1.25, s.camera.exposure_frames, 0);
  CHECK_EQUAL(99u, s.seed);
  DOUBLES_EQUAL(1.0, s.duration_s, 0);
}

// A key given twice, at any level, would be read once and the other value
// ignored (a rendered recording byte for byte the first value's): refused.
TEST(ScenarioErrors, AKeyGivenTwiceIsRefused) {
  std::string e = error_of(replace(kGood, "  rate_hz: 60\n", "  rate_hz: 60\n  rate_hz: 30\n"));
  STRCMP_CONTAINS("bad.yaml:5: key 'rate_hz' is given again (first at line 4)", e.c_str());
  e = error_of(replace(kGood, "duration_s: 2\n", "duration_s: 2\nduration_s: 3\n"));
  STRCMP_CONTAINS("bad.yaml:2: key 'duration_s' is given again", e.c_str());
}

// Frame times must stay inside the format's signed 64-bit nanoseconds and
// after the recording's start: a start_ns near 2^63 and a negative
// first_frame_s wrapped (the render passed, run refused its output).
TEST(ScenarioErrors, TimesThatLeaveTheFormatAreRefused) {
  std::string e = error_of(std::string("start_ns: 9223372036854775000\n") + kGood);
  STRCMP_CONTAINS("bad.yaml:1: 'start_ns' must be a whole number of nanoseconds in 0..4e18", e.c_str());
  e = error_of(replace(kGood, "  rate_hz: 60\n", "  rate_hz: 60\n  first_frame_s: -2\n"));
  STRCMP_CONTAINS("bad.yaml:5:", e.c_str());
  STRCMP_CONTAINS("first_frame_s", e.c_str());
}

// The seed, the resolution and dropped frames are read as start_ns and the
// command lines read whole numbers (was: 'seed: 010' rendered with seed 10
// and '1e3' with 1000, 'resolution: [040, 30]' at 40 columns, 'frames:
// [010]' dropped frame 10, where '--seed 010' and '--resolution 040x30' are
// refused and YAML 1.1 readers take 010 as 8).
TEST(ScenarioErrors, WholeNumbersAreReadAsTheCommandLinesReadThem) {
  STRCMP_EQUAL("bad.yaml:1: 'seed' must be a whole number in 0..9007199254740992, written without a leading zero, "
               "not '010'",
               error_of(std::string("seed: 010\n") + kGood).c_str());
  STRCMP_EQUAL("bad.yaml:1: 'seed' must be a whole number in 0..9007199254740992, not '1e3'",
               error_of(std::string("seed: 1e3\n") + kGood).c_str());
  STRCMP_EQUAL("bad.yaml:1: 'seed' must be a whole number in 0..9007199254740992, not '5.5'",
               error_of(std::string("seed: 5.5\n") + kGood).c_str());
  CHECK_EQUAL(7u, parse_scenario(std::string("seed: 7\n") + kGood, "good.yaml").seed);
  STRCMP_EQUAL("bad.yaml:3: 'resolution' must be a whole number in 1..16384 (pixels), written without a leading "
               "zero, not '040'",
               error_of(replace(kGood, "resolution: [40, 30]", "resolution: [040, 30]")).c_str());
  STRCMP_EQUAL("bad.yaml:3: 'resolution' must be a whole number in 1..16384 (pixels), not '30.5'",
               error_of(replace(kGood, "resolution: [40, 30]", "resolution: [40, 30.5]")).c_str());
  STRCMP_EQUAL("bad.yaml:14: 'frames' must be a whole number in 0..1000000000 (frame numbers), written without a "
               "leading zero, not '010'",
               error_of(std::string(kGood) + "drops: {frames: [3, 010]}\n").c_str());
  // A list or a map where the number belongs (was: "not '?'").
  STRCMP_EQUAL("bad.yaml:1: 'seed' must be a whole number in 0..9007199254740992, not a list",
               error_of(std::string("seed: [7]\n") + kGood).c_str());
  STRCMP_EQUAL("bad.yaml:14: 'frames' must be a whole number in 0..1000000000 (frame numbers), not a map",
               error_of(std::string(kGood) + "drops: {frames: [{a: 1}]}\n").c_str());
}

// start_ns is read as the command lines read whole numbers: yaml-cpp read
// C's base-0 forms ('010' as 8 ns, '0x10' as 16), the seed's reader 010 as 10.
TEST(ScenarioErrors, AStartTimeInOctalOrHexadecimalIsRefused) {
  std::string e = error_of(std::string("start_ns: 010\n") + kGood);
  STRCMP_CONTAINS("bad.yaml:1: 'start_ns' must be a whole number of nanoseconds in 0..4e18 (timestamps must stay within "
                  "signed 64 bits), written without a leading zero, not '010'",
                  e.c_str());
  e = error_of(std::string("start_ns: 0x10\n") + kGood);
  STRCMP_CONTAINS("bad.yaml:1: 'start_ns' must be a whole number of nanoseconds in 0..4e18 (timestamps must stay within "
                  "signed 64 bits), not '0x10'",
                  e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string("start_ns: 0\n") + kGood).c_str());
  CHECK_EQUAL(1000000010LL, parse_scenario(std::string("start_ns: 1000000010\n") + kGood, "good.yaml").start_ns);
}

// The gyro's first sample time became int64 nanoseconds: imu offset_s 1e300
// overflowed them and the render hung stepping from the wrapped time.
TEST(ScenarioErrors, AGyroOffsetBeyondTheRangeIsRefused) {
  std::string e = error_of(std::string(kGood) + "imu: {offset_s: 1e300}\n");
  STRCMP_CONTAINS("bad.yaml:14: 'offset_s' = 1e+300 is out of range [-1e+06, 1e+06]", e.c_str());
  e = error_of(std::string(kGood) + "imu: {offset_s: -2e6}\n");
  STRCMP_CONTAINS("bad.yaml:14: 'offset_s' = -2e+06 is out of range", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string(kGood) + "imu: {offset_s: 0.0013}\n").c_str());
}

// YAML::Load reads the first document only: a second one (after '---'), or
// text after a '...' end marker, was ignored and the render made without it.
TEST(ScenarioErrors, ASecondDocumentIsRefused) {
  std::string e = error_of(std::string(kGood) + "---\nduration_s: 5\n");
  STRCMP_CONTAINS("bad.yaml:14: a second YAML document (after '---')", e.c_str());
  e = error_of(std::string(kGood) + "...\n# a comment\nseed: 7\n");
  STRCMP_CONTAINS("bad.yaml:16: text after the end of the document ('...' at line 14)", e.c_str());
  // A '---' before the content (a document start marker), a final '...' and
  // '---' inside a quoted text stay what they are.
  STRCMP_EQUAL("(accepted)", error_of(std::string("# a scenario\n---\n") + kGood + "...\n\n").c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string("description: \"a\n  --- b\"\n") + kGood).c_str());
  // A directive and the '---' it heads: one document (was: 'bad.yaml:2: a
  // second YAML document (after '---')').
  STRCMP_EQUAL("(accepted)", error_of(std::string("%YAML 1.2\n---\n") + kGood).c_str());
  e = error_of(std::string(kGood) + "---\n%YAML 1.2\n---\nduration_s: 5\n");
  STRCMP_CONTAINS("bad.yaml:14: a second YAML document (after '---')", e.c_str());
}

// Brackets nested hundreds deep stop yaml-cpp's parser with "bad file"
// (was: 'YAML syntax: bad file', exit 1 with no rule said).
TEST(ScenarioErrors, NestingTooDeepSaysSo) {
  const std::string e = error_of(std::string(kGood) + "seed: " + std::string(600, '[') + std::string(600, ']') + "\n");
  STRCMP_CONTAINS("bad.yaml:14: YAML nested ", e.c_str());
  STRCMP_CONTAINS(" levels deep, as deep as the YAML reader goes: a scenario is one map of KEY: VALUE lines", e.c_str());
}

// Aliases of aliases ("billion laughs"): 12 lines that expand to 9^12 values.
// The check for repeated keys visited each of them: the render hung.
TEST(ScenarioErrors, AliasesThatMultiplyAreRefused) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 12; ++i) {
    const std::string p = "*a" + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + p;
    for (int k = 1; k < 9; ++k) bomb += ", " + p;
    bomb += "]\n";
  }
  const std::string e = error_of(bomb + kGood);
  STRCMP_CONTAINS("bad.yaml:", e.c_str());
  STRCMP_CONTAINS(": the file's aliases (*NAME) expand it to more than 1000000 values", e.c_str());
  // An alias used a few times is a value shared, as meant.
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, "{type: uniform, value: 90}", "&p {type: uniform, value: 90}") +
                                      "    - {from: [0, -2], to: [5, -2], z: [-1, 1], pattern: *p}\n").c_str());
}

// A list or a map where a key or a text belongs: yaml-cpp's conversion threw
// and the message was "bad.yaml:1: bad conversion", naming no key, no rule.
TEST(ScenarioErrors, AListWhereTextOrAKeyBelongsIsNamed) {
  std::string e = error_of(std::string("description: [a, b]\n") + kGood);
  STRCMP_CONTAINS("bad.yaml:1: 'description' must be text, not a list or a map", e.c_str());
  e = error_of(replace(kGood, "    - from: [0, 2]\n", "    - name: {a: 1}\n      from: [0, 2]\n"));
  STRCMP_CONTAINS("bad.yaml:10: 'name' must be text, not a list or a map", e.c_str());
  e = error_of(replace(kGood, "  rate_hz: 60\n", "  [rate_hz]: 60\n"));
  STRCMP_CONTAINS("bad.yaml:4: a key in 'camera' must be a word, not a list or a map", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string("description:\n") + kGood).c_str());
}

// A key with no value was named at the next token's line: 'duration_s:'
// before 'camera:' said 'bad.yaml:2: 'duration_s' must be a number', a
// 'rate_hz:' at the end of its map the line of the map after it.
TEST(ScenarioErrors, AKeyWithoutAValueNamesItsLine) {
  STRCMP_EQUAL("bad.yaml:1: 'duration_s' has no value (empty, or null)",
               error_of(replace(kGood, "duration_s: 2\n", "duration_s:\n")).c_str());
  STRCMP_EQUAL("bad.yaml:4: 'rate_hz' has no value (empty, or null)",
               error_of(replace(kGood, "  rate_hz: 60\n", "  rate_hz:\n")).c_str());
  STRCMP_EQUAL("bad.yaml:12: 'z' has no value (empty, or null)",
               error_of(replace(kGood, "      z: [-1, 1]\n", "      z: ~\n")).c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, "    - from: [0, 2]\n", "    - name:\n      from: [0, 2]\n")).c_str());
}

// drops.frames: a frame past the recording's end was ignored and a frame
// listed twice counted once, silently (the list said more than was dropped).
TEST(ScenarioErrors, DroppedFramesBeyondTheRecordingOrRepeatedAreRefused) {
  // kGood: 2 s at 60 Hz, frames 0..119.
  std::string e = error_of(std::string(kGood) + "drops: {frames: [3, 120]}\n");
  STRCMP_CONTAINS("bad.yaml:14: 'frames' = 120 is not a frame of the recording: frame numbers must be below its frame "
                  "count, 120 (duration_s 2 s x rate_hz 60 Hz)", e.c_str());
  e = error_of(std::string(kGood) + "drops:\n  frames:\n    - 5\n    - 119\n    - 5\n");
  STRCMP_CONTAINS("bad.yaml:18: 'frames' lists frame 5 again (first at line 16): each frame once", e.c_str());
  // A later first frame leaves fewer frames: 0.5 s + i / 60 < 2 s for i < 90.
  e = error_of(replace(kGood, "  rate_hz: 60\n", "  rate_hz: 60\n  first_frame_s: 0.5\n") + "drops: {frames: [90]}\n");
  STRCMP_CONTAINS("bad.yaml:15: 'frames' = 90 is not a frame of the recording: frame numbers must be below its frame "
                  "count, 90 (duration_s 2 s x rate_hz 60 Hz, from first_frame_s)", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(std::string(kGood) + "drops: {frames: [0, 60, 119]}\n").c_str());
  STRCMP_EQUAL("(accepted)",
               error_of(replace(kGood, "  rate_hz: 60\n", "  rate_hz: 60\n  first_frame_s: 0.5\n") + "drops: {frames: [89]}\n").c_str());
}

// A sinusoid pattern spans mean +- amplitude: an amplitude above the mean went
// below 0 and was clipped to black, silently. A brightness cannot be negative.
// (The lighting flicker, 1 + a sin, already holds a to [0, 1]; a speed may be
// negative: a rig that reverses.)
TEST(ScenarioErrors, ASinusoidGoingBelowBlackIsRefused) {
  const std::string wall = "{type: uniform, value: 90}";
  std::string e = error_of(replace(kGood, wall, "{type: sinusoid, mean: 100, amplitude: 150}"));
  STRCMP_CONTAINS("bad.yaml:13: sinusoid 'amplitude' = 150 is larger than its 'mean' = 100: the brightness, mean - "
                  "amplitude at the troughs, would go below 0 and be clipped to black; a brightness cannot be negative, "
                  "so amplitude must be at most the mean", e.c_str());
  // The default amplitude (127) with a darker mean.
  e = error_of(replace(kGood, wall, "{type: sinusoid, mean: 60, combine: product}"));
  STRCMP_CONTAINS("bad.yaml:13: sinusoid 'amplitude' = 127 is larger than its 'mean' = 60", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, wall, "{type: sinusoid, mean: 127.5, amplitude: 127.5}")).c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, "speed: 0.5", "speed: [0.5, -0.5], profile: smooth")).c_str());
}

// And above 255 it was clipped to white, silently (the crests flattened, the
// mean lowered): refused the same way.
TEST(ScenarioErrors, ASinusoidGoingAboveWhiteIsRefused) {
  const std::string wall = "{type: uniform, value: 90}";
  std::string e = error_of(replace(kGood, wall, "{type: sinusoid, mean: 200, amplitude: 100}"));
  STRCMP_CONTAINS("bad.yaml:13: sinusoid 'mean' = 200 plus its 'amplitude' = 100 is 300: the brightness, mean + "
                  "amplitude at the crests, would go above 255 (white) and be clipped; amplitude must be at most 255 - "
                  "mean",
                  e.c_str());
  // The default amplitude (127) with a brighter mean.
  e = error_of(replace(kGood, wall, "{type: sinusoid, mean: 129, combine: product}"));
  STRCMP_CONTAINS("bad.yaml:13: sinusoid 'mean' = 129 plus its 'amplitude' = 127 is 256", e.c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, wall, "{type: sinusoid, mean: 200, amplitude: 55}")).c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(kGood, wall, "{type: sinusoid, mean: 128}")).c_str());  // the defaults
}

// A number in a refusal is the value read, in full: the messages printed six
// digits, so 'rate_hz: 10000.0001' said "'rate_hz' = 10000 is out of range
// [0.1, 10000]", a refusal its own rule allows (a sum of mean and amplitude
// just above 255 said 255, a frame number 1.23457e+06, a sample count 1e+07).
TEST(ScenarioErrors, ANumberInARefusalIsTheValueInFull) {
  std::string e = error_of(replace(kGood, "rate_hz: 60", "rate_hz: 10000.0001"));
  STRCMP_CONTAINS("bad.yaml:4: 'rate_hz' = 10000.0001 is out of range [0.1, 10000]", e.c_str());
  e = error_of(replace(kGood, "speed: 0.5", "speed: -1000.0000001"));
  STRCMP_CONTAINS("bad.yaml:7: 'speed' = -1000.0000001 is out of range [-1000, 1000]", e.c_str());
  e = error_of(replace(kGood, "{type: uniform, value: 90}", "{type: sinusoid, mean: 127.5000001, amplitude: 127.5}"));
  STRCMP_CONTAINS("bad.yaml:13: sinusoid 'mean' = 127.5000001 plus its 'amplitude' = 127.5 is 255.0000001: ",
                  e.c_str());
  e = error_of(std::string(kGood) + "drops: {frames: [1234567]}\n");
  STRCMP_CONTAINS("bad.yaml:14: 'frames' = 1234567 is not a frame of the recording: frame numbers must be below its "
                  "frame count, 120 (duration_s 2 s x rate_hz 60 Hz)",
                  e.c_str());
  Scenario s = parse_scenario(replace(kGood, "duration_s: 2\n", "duration_s: 200000.0001\n"), "big.yaml");
  s.imu.rate_hz = 100;
  s.groundtruth_rate_hz = 100;
  try {
    check_render_size(s);
    FAIL("accepted");
  } catch (const ScenarioError& x) {
    STRCMP_EQUAL("big.yaml: camera rate_hz = 60 Hz for duration_s = 200000.0001 s is 12000001 frame pairs: a render "
                 "makes at most 10000000 (shorten the duration or lower the rate)",
                 x.what());
  }
}

// The scenario's file name is shown as its words are (4861290): a scenario
// named 'sc<ESC>[2J.yaml' sent the escape sequence to the terminal with each
// refusal ('sc[2J.yaml:4: ...'), the YAML reader's and the size check's too.
TEST(ScenarioErrors, TheScenariosNameIsShownLikeAField) {
  try {
    parse_scenario(replace(kGood, "rate_hz: 60", "rate_hz: -5"), "sc\x1b[2J.yaml");
    FAIL("accepted");
  } catch (const ScenarioError& e) {
    STRCMP_CONTAINS("sc\\x1B[2J.yaml:4: 'rate_hz' = -5 is out of range", e.what());
  }
  try {
    parse_scenario("duration_s: [1\n", "sc\x1b[2J.yaml");
    FAIL("accepted");
  } catch (const ScenarioError& e) {
    STRCMP_CONTAINS("sc\\x1B[2J.yaml:2: YAML syntax: ", e.what());
  }
  Scenario s = parse_scenario(replace(kGood, "duration_s: 2\n", "duration_s: 200000\n"), "sc\x1b[2J.yaml");
  try {
    check_render_size(s);
    FAIL("accepted");
  } catch (const ScenarioError& e) {
    STRCMP_CONTAINS("sc\\x1B[2J.yaml: camera rate_hz = 60 Hz for duration_s = 200000 s is ", e.what());
  }
}

// vibration: the block read, its keys and ranges refused as the others are.
TEST(ScenarioErrors, Vibration) {
  const std::string good = std::string(kGood) + "vibration: {pitch_deg: 1.0, roll_deg: 0.5, heave_m: 0.005, frequency_hz: [3, 11]}\n";
  const Scenario s = parse_scenario(good, "good.yaml");
  DOUBLES_EQUAL(1.0, s.vibration.pitch_rms_deg, 0);
  DOUBLES_EQUAL(0.5, s.vibration.roll_rms_deg, 0);
  DOUBLES_EQUAL(0.005, s.vibration.heave_rms_m, 0);
  DOUBLES_EQUAL(3, s.vibration.freq_lo_hz, 0);
  DOUBLES_EQUAL(11, s.vibration.freq_hi_hz, 0);
  CHECK(parse_scenario(kGood, "good.yaml").vibration.none());
  STRCMP_CONTAINS("bad.yaml:14: unknown key 'yaw_deg' in 'vibration' (allowed: pitch_deg, roll_deg, heave_m, frequency_hz)",
                  error_of(replace(good, "roll_deg", "yaw_deg")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'pitch_deg' = 25 is out of range [0, 20]",
                  error_of(replace(good, "pitch_deg: 1.0", "pitch_deg: 25")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'roll_deg' = -1 is out of range [0, 20]",
                  error_of(replace(good, "roll_deg: 0.5", "roll_deg: -1")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'heave_m' = 0.6 is out of range [0, 0.5]",
                  error_of(replace(good, "heave_m: 0.005", "heave_m: 0.6")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'frequency_hz' = 0 is out of range [0.01, 100]",
                  error_of(replace(good, "[3, 11]", "[0, 11]")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'frequency_hz' = 150 is out of range [0.01, 100]",
                  error_of(replace(good, "[3, 11]", "[3, 150]")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'frequency_hz' = [11, 3] must be [low, high] with low <= high",
                  error_of(replace(good, "[3, 11]", "[11, 3]")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'frequency_hz' must be a list of 2 numbers",
                  error_of(replace(good, "[3, 11]", "5")).c_str());
  STRCMP_CONTAINS("bad.yaml:14: 'vibration' needs 'frequency_hz: [low, high]' (Hz)",
                  error_of(replace(good, ", frequency_hz: [3, 11]", "")).c_str());
  STRCMP_EQUAL("(accepted)", error_of(replace(good, "[3, 11]", "[7, 7]")).c_str());
}
