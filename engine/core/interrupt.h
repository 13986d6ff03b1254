#pragma once
// SIGINT and SIGTERM as a request to stop. Long jobs poll interrupted() between chunks of work,
// finish the chunk in flight, write what has converged (every output whole, atomic_files.h) and
// exit with interrupt_exit_code(): 128 + the signal, 130 or 143, as a shell reports a process
// the signal ended. A second signal exits at once with that code, after removing the temporaries
// of the files being written, so that no partial file is left.
#include <string>

namespace mvpl {

// Installs the handlers (once, at start-up).
void install_interrupt_handlers();
// Whether a first SIGINT or SIGTERM arrived.
bool interrupted();
// 128 + the first signal, or 0 when none arrived.
int interrupt_exit_code();

// The temporaries of files being written (atomic_files.cpp), which a second signal removes.
void track_temporary(const std::string& path);
void untrack_temporary(const std::string& path);

}  // namespace mvpl
