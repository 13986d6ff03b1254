#pragma once
// The check every reader of an input file makes before opening it. Opening a FIFO blocks until a
// writer comes (forever, for `mkfifo x.ply`), a device or kernel pseudo-file may never end
// (/dev/zero, /proc/kcore), and a folder reads as an empty or failing stream: none is an input.
#include <string>

namespace mvpl {

// Throws InputError(path, …) naming what `path` is instead, unless it names an existing regular
// file (after following symbolic links) outside /proc and /sys.
void require_regular_file(const std::string& path);

}  // namespace mvpl
