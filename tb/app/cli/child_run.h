// A stereosim child process as the campaign and the sweep start it: argv[0]
// the program, stdout and stderr into one log file (posix_spawn, no shell).
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace cli {

// Starts args[0] with args; -1 and *error (one line) if it cannot start.
pid_t spawn_logged(const std::vector<std::string>& args, const std::string& log_path,
                   std::string* error);

// The last non-empty line of a text file ("" if none): why a child failed.
std::string last_line_of(const std::string& path);

}  // namespace cli
