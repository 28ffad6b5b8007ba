// Why a path cannot be read, or written, in words, checked before it is
// opened: a folder, a FIFO, a device node or a symlink loop each get their
// own reason instead of "does not exist" or "empty file", and a FIFO or
// /dev/zero is never opened (reading one would hang or never end). Outputs
// are checked before the work that fills them, not after it.
#pragma once
#include <string>

namespace lumavel::host {

// "" when `path` (symlinks followed) is a regular file; otherwise the reason,
// with `what` the kind of file expected, e.g. "does not exist", "is a folder,
// not a configuration file", "is a FIFO (named pipe), not a configuration
// file", "is a loop of symbolic links".
std::string why_not_a_file(const std::string& path, const std::string& what = "file");
// "" when `path` is a folder; otherwise the reason, e.g. "is a file, not a
// recording folder" (what = "recording folder").
std::string why_not_a_folder(const std::string& path, const std::string& what = "folder");
// "" when a `what` can be written at `path`: an existing file or special file
// (written in place), or a new name in a folder that can be written to;
// otherwise the reason, e.g. "is a folder, not a plot file", "cannot be
// created: its folder out does not exist".
std::string why_not_writable(const std::string& path, const std::string& what = "file");
// False only when nothing is at `path` (an optional input that is absent):
// anything else there, readable or not, is for why_not_a_file to judge.
bool path_present(const std::string& path);
// `path` as a message shows it: in full up to 200 characters, else its start
// and end with the length ("aaa...zzz (5000 characters)").
std::string shown_path(const std::string& path);

}  // namespace lumavel::host
