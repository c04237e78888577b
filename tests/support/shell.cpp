#include "tests/support/shell.h"

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace testsupport {

namespace {

// The folders temp_dir made, removed when the test program ends with every
// test passed (a failure's folders stay to be looked at); each ctest run
// left about a hundred in /tmp. A test's forked child must leave with
// _exit (as they do): exit() would run this in the child.
class temp_dirs {
  public:
    void add(const std::string& dir) { m_dirs.push_back(dir); }
    ~temp_dirs() {
        if (!::testing::UnitTest::GetInstance()->Passed()) return;
        std::error_code ignored;
        for (const std::string& dir : m_dirs) std::filesystem::remove_all(dir, ignored);
    }

  private:
    std::vector<std::string> m_dirs;
};

temp_dirs& made_dirs() {
    static temp_dirs dirs;
    return dirs;
}

}  // namespace

command_result run_command(const std::string& command) {
    command_result r;
    std::FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return r;
    char buffer[4096];
    size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, p)) > 0) r.output.append(buffer, n);
    const int status = pclose(p);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string temp_dir(const std::string& prefix) {
    std::string pattern = "/tmp/" + prefix + "-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const char* dir = mkdtemp(name.data());
    if (!dir) return "";
    made_dirs().add(dir);
    return dir;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool file_exists(const std::string& path) {
    return access(path.c_str(), F_OK) == 0;
}

}  // namespace testsupport
