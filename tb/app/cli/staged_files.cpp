#include "tb/app/cli/staged_files.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "tb/platform/firmware_crash.h"

namespace cli {

namespace fs = std::filesystem;

staged_files::~staged_files() {
    discard();
}

bool staged_files::open(const std::string& dir, std::string* error) {
    std::error_code ec;
    const bool existed = fs::exists(dir, ec);
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
        *error = "cannot create output folder '" + dir +
                 "': " + (ec ? ec.message() : std::string("not a folder"));
        return false;
    }
    const std::string staging =
        (fs::path(dir) / (".stereosim-staging-" + std::to_string(getpid()))).string();
    fs::remove_all(staging, ec);
    if (!fs::create_directory(staging, ec) || ec) {
        *error = "cannot write to output folder '" + dir +
                 "': " + (ec ? ec.message() : std::string("cannot create a file there"));
        return false;
    }
    // A folder we may create in but not write files to (odd ACLs) fails here, not at the end.
    const std::string probe = (fs::path(staging) / ".probe").string();
    if (!std::ofstream(probe)) {
        fs::remove_all(staging, ec);
        *error = "cannot write to output folder '" + dir + "': " + std::strerror(errno);
        return false;
    }
    fs::remove(probe, ec);
    m_dir = dir;
    m_staging = staging;
    platform::remove_on_firmware_failure(staging, existed ? std::string() : dir);
    return true;
}

std::string staged_files::staged_path(const std::string& relative) {
    const fs::path path = fs::path(m_staging) / relative;
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    m_relative.push_back(relative);
    return path.string();
}

bool staged_files::commit(std::string* error) {
    for (const std::string& relative : m_relative) {
        const fs::path from = fs::path(m_staging) / relative;
        const fs::path to = fs::path(m_dir) / relative;
        std::error_code ec;
        if (!fs::exists(from, ec)) continue;  // a writer that chose not to write it
        fs::create_directories(to.parent_path(), ec);
        fs::rename(from, to, ec);
        if (ec) {
            *error = "cannot move " + to.string() + " into place: " + ec.message();
            return false;
        }
        m_committed.push_back(to.string());
    }
    discard();
    return true;
}

void staged_files::discard() {
    if (m_staging.empty()) return;
    platform::remove_on_firmware_failure("", "");
    std::error_code ec;
    fs::remove_all(m_staging, ec);
    m_staging.clear();
}

}  // namespace cli
