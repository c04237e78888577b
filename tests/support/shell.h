// What the command-line tests share: running a command as a user would
// (stdout and stderr together, the exit code), a fresh temporary folder,
// a file's text.
#pragma once

#include <string>

namespace testsupport {

struct command_result {
    int exit_code = -1;  // -1: could not run, or killed
    std::string output;  // stdout + stderr
};

command_result run_command(const std::string& command);
// A new folder /tmp/<prefix>-XXXXXX ("" if it cannot be made), removed at
// the test program's end if every test passed.
std::string temp_dir(const std::string& prefix);
std::string read_text(const std::string& path);  // "" if unreadable
bool file_exists(const std::string& path);

}  // namespace testsupport
