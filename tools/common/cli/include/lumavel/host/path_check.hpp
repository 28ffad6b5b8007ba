// Why a path cannot be read, or written, in words, checked before it is
// opened: a folder, a FIFO, a device node or a symlink loop each get their
// own reason instead of "does not exist" or "empty file", and a FIFO or
// /dev/zero is never opened (reading one would hang or never end). Outputs
// are checked before the work that fills them, not after it.
#pragma once
#include <cstdio>
#include <map>
#include <string>
#include <utility>

namespace lumavel::host {

// "" when `path` (symlinks followed) is a regular file; otherwise the reason,
// with `what` the kind of file expected, e.g. "does not exist", "is a folder,
// not a configuration file", "is a FIFO (named pipe), not a configuration
// file", "is a loop of symbolic links", "is a symbolic link to /gone/x.csv,
// which does not exist".
std::string why_not_a_file(const std::string& path, const std::string& what = "file");
// What the kernel says a character device node is, from sysfs
// (/sys/dev/char/MAJ:MIN): its subsystem ("hidraw", "hidg", "misc", "mem",
// "tty") and its own name ("hidraw0", "hidg0", "uhid", "null"); both "" when
// sysfs does not say (not mounted, or no such node).
struct CharDevice {
  unsigned major = 0, minor = 0;
  std::string subsystem, name;
};
CharDevice char_device_of(const std::string& path);
// "" when `path` (symlinks followed) is a character device node, such as
// /dev/uhid or /dev/hidg0; otherwise the reason, e.g. "is a regular file, not
// a uhid device node" (what = "uhid device node"). With `subsystem` or
// `name` given, the node must also be that device where sysfs says what it
// is (/dev/zero for a hidg node was read for ever): "is the character device
// 1:5 (mem null), not a HID gadget device node".
std::string why_not_a_device(const std::string& path, const std::string& what, const std::string& subsystem = "",
                             const std::string& name = "");
// "" when `path` is a folder; otherwise the reason, e.g. "is a file, not a
// recording folder" (what = "recording folder").
std::string why_not_a_folder(const std::string& path, const std::string& what = "folder");
// "" when a `what` can be written at `path`: an existing file or special file
// (written in place), or a new name in a folder that can be written to;
// otherwise the reason, e.g. "is a folder, not a plot file", "cannot be
// created: its folder out does not exist", "is a symbolic link to
// /gone/x.csv, which cannot be created: its folder /gone does not exist"
// (a dangling link is written through), or for "-" (standard output,
// which the callers that can write there take before asking) "'-' stands for
// standard output, where no plot file is written: ...".
std::string why_not_writable(const std::string& path, const std::string& what = "file");
// "" when an output folder `path` can be written in: one that is there must
// be a folder that may be written in ("no permission to write in it"); one
// that is not is made with the folders missing on its way, under the nearest
// part of its path that is there, which must be such a folder ("cannot be
// created: its folder lnk is a symbolic link to /gone, which does not exist",
// "... no permission to write in its folder ro"). `what` names the folder in
// "is a file, not a `what`".
std::string why_not_a_writable_folder(const std::string& path, const std::string& what = "folder");
// The name an output is written under before it is renamed to `path`: beside
// it (one file system), "PATH.tmpPID-N", N counting the names given in this
// process; the name before the suffix cut where the whole would be longer
// than a name may be (a legal 255-character output name was refused as 'File
// name too long', said of its temporary name).
std::string temporary_name_for(const std::string& path);
// For a `path` that does not exist: " (NAME.tmpPID-N lies beside it: ...)"
// when a temporary name temporary_name_for gave it is there, the output of a
// write stopped before its end (a render interrupted by Ctrl-C), else "".
std::string left_by_a_stopped_write(const std::string& path);
// Where a file written at `path` lands, absolute and normal (weakly_canonical),
// for telling whether two outputs, or an output and an input, are one file:
// `path` itself, or for a symbolic link to nothing, which a write follows and
// creates, its target (weakly_canonical keeps such a link's own name, and a
// link to the -o file's name, not yet written, passed as another file). ""
// when it cannot be said.
std::string written_path(const std::string& path);
// The regular file standard output is (a shell's '> FILE'), as its absolute
// path, for telling whether an output the tool writes by name is the file its
// standard output writes too: a CSV streamed to standard output, then a plot
// of the same file renamed into place, left the plot alone, exit 0. "" when
// standard output is no regular file (a terminal, a pipe, /dev/null) or its
// path cannot be said (a file removed since).
std::string standard_output_file();
// The reason "-" is refused where an output cannot go to standard output:
// "'-' stands for standard output, where no `what` is written: give a `kind`
// name (./- for a `kind` of that name)" (kind: "file", or "folder" for an
// output folder such as render's OUT).
std::string why_dash_is_not_an_output(const std::string& what, const std::string& kind = "file");
// "" unless `out` (a recording folder to write, whose frames go to out/mav0)
// names a mav0 folder itself, which would become out/mav0/mav0; otherwise the
// reason, e.g. "rec/mav0 is a recording's mav0 folder (...: this would make
// rec/mav0/mav0): give rec".
std::string why_inner_mav0(const std::string& out);
// How long an output that is a FIFO (named pipe) waits for a process to read
// it (`run -o FIFO & reader FIFO` may start the reader a moment later).
constexpr int kFifoReaderWaitMs = 2000;
// Opens `path` for writing as std::fopen(path, mode) does ("w", "wb"),
// except that a FIFO nobody reads is not waited on forever: it is opened when
// a reader comes within kFifoReaderWaitMs, else refused. nullptr on failure,
// with `why` the reason: "is a FIFO (named pipe) that no process reads (...)"
// or the system's (strerror).
std::FILE* open_for_writing(const std::string& path, const char* mode, std::string& why);
// The text files the tools read whole (a sensor.yaml, a scenario, a
// configuration file) hold a few hundred lines at most: anything bigger is
// something else (a disk image, a video under the wrong name), refused by its
// size before it is read into memory.
constexpr unsigned long long kMaxTextFileBytes = 1ull << 20;
// "" when the regular file `path` is at most kMaxTextFileBytes (or its size
// cannot be had: the reader's own error says why); otherwise "the file is N
// bytes: " + `holds` + " (at most ... bytes are read)", with `holds` what such
// a file holds, e.g. "a sensor.yaml holds a few keys".
std::string why_too_big_for_text(const std::string& path, const std::string& holds);
// False only when nothing is at `path` (an optional input that is absent):
// anything else there, readable or not, a dangling symbolic link included,
// is for why_not_a_file to judge.
bool path_present(const std::string& path);
// True when `path` is `folder` or lies inside it, symlinks resolved (what a
// remove_all of `folder` would take with it).
bool lies_inside(const std::string& path, const std::string& folder);
// "" when the file name `name` (from a table or a scenario) has no NUL byte;
// otherwise "'a.png' is followed by a NUL byte inside the name (character
// 6): the system would read the name only up to it" (and open a.png).
std::string why_nul_in_name(const std::string& name);
// The frame files named by the rows of a table (a cam*/data.csv, a slider
// dataset's images.txt): each row names its own image, a repeated one would
// read as a standstill.
class FrameNames {
 public:
  // "" the first time `name` is seen (names compared lexically normalised:
  // './x.png' is 'x.png'); else "filename 'x.png' is also the frame of line
  // 7: each row names its own image (...)". With `path` (where `name` is on
  // the disk) the file itself is compared too, by device and inode: a name
  // that is a symbolic or hard link to an earlier row's file is "filename
  // 'y.png' is the same file as 'x.png', the frame of line 7 (a link to it):
  // each row names its own image (...)". A path that cannot be examined is
  // left to why_not_a_file.
  std::string why_repeated(const std::string& name, long line, const std::string& path = "");
  // The rows that follow are of another table (cam1/data.csv after
  // cam0/data.csv): their names are read from another folder, but a file of
  // an earlier table is still refused, "... the frame of line 50 of
  // REC/mav0/cam0/data.csv (a link to it) ...".
  void next_table(const std::string& table);

 private:
  struct Seen {
    long line;
    std::string name, table;
  };
  std::string table_;
  std::map<std::string, long> line_of_;
  std::map<std::pair<unsigned long long, unsigned long long>, Seen> file_of_;
};
// `path` (or a field, a line read from a file) as a message shows it: in full
// up to 200 characters, else its start and end with the length ("aaa...zzz
// (5000 characters)"); ASCII control characters are shown as \xNN, never
// sent to the terminal as they are (a binary file's escape sequences).
std::string shown_path(const std::string& path);
// `text` as shown_path shows it, but in full, never shortened: for a message
// that holds a value somewhere inside it (a command-line parser's).
std::string shown_text(const std::string& text);

}  // namespace lumavel::host
