#include "tb/app/cli/firmware_check.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "tb/firmware/builtin.h"
#include "tb/app/cli/child_run.h"
#include "tb/app/cli/host_figures.h"
#include "tb/app/cli/run_command.h"
#include "tb/firmware/plugin.h"

namespace cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Two fault rows of the smoke plan that share a snapshot group (one seed,
// length and setting), so the campaign forks both from its fault-free run.
constexpr const char* forked_rows = "skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@frame=4";
constexpr int check_frames = 12;

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The commands, at most two at a time; false + *error (with the failing
// command's last line) if one could not run. Exit codes up to `ok_up_to`
// are results (1: over budget, or the contract broken).
bool run_all(const std::vector<std::vector<std::string>>& commands, const fs::path& dir,
             std::string* error) {
    std::vector<std::pair<pid_t, std::string>> running;
    bool ok = true;
    const auto reap = [&]() {
        int status = 0;
        const pid_t pid = wait(&status);
        for (auto it = running.begin(); it != running.end(); ++it) {
            if (it->first != pid) continue;
            const bool result = WIFEXITED(status) && WEXITSTATUS(status) <= 1;
            if (!result && ok) {
                ok = false;
                *error = "a check run failed: " + last_line_of(it->second);
            }
            running.erase(it);
            return;
        }
    };
    for (size_t i = 0; i < commands.size(); ++i) {
        if (running.size() == 2) reap();
        const std::string log = (dir / ("log-" + std::to_string(i) + ".txt")).string();
        const pid_t pid = spawn_logged(commands[i], log, error);
        if (pid < 0) {
            ok = false;
            break;
        }
        running.emplace_back(pid, log);
    }
    while (!running.empty()) reap();
    return ok;
}

// The first difference between two runs' outputs, "" if none.
std::string compare_runs(const fs::path& a, const fs::path& b) {
    json ra, rb;
    try {
        ra = json::parse(read_text(a / "report.json"));
        rb = json::parse(read_text(b / "report.json"));
    } catch (const std::exception& e) {
        return std::string("a report.json is unreadable: ") + e.what();
    }
    const std::string in_report =
        first_difference(without_host_figures(ra), without_host_figures(rb));
    if (!in_report.empty()) return "report.json " + in_report;
    if (read_text(a / "frames.csv") != read_text(b / "frames.csv")) return "frames.csv";
    return "";
}

std::vector<std::string> with_firmware(std::vector<std::string> args, const std::string& path) {
    if (!path.empty()) {
        args.push_back("--firmware");
        args.push_back(path);
    }
    return args;
}

}  // namespace

std::string first_difference(const json& a, const json& b, const std::string& path) {
    const std::string here = path.empty() ? "the top level" : path;
    if (a.type() != b.type()) return here + " (" + a.dump() + " / " + b.dump() + ")";
    if (a.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it) {
            const std::string sub = path.empty() ? it.key() : path + "." + it.key();
            if (!b.contains(it.key())) return sub + " (only in the first)";
            const std::string d = first_difference(it.value(), b.at(it.key()), sub);
            if (!d.empty()) return d;
        }
        for (auto it = b.begin(); it != b.end(); ++it)
            if (!a.contains(it.key()))
                return (path.empty() ? it.key() : path + "." + it.key()) + " (only in the second)";
        return "";
    }
    if (a.is_array()) {
        for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
            const std::string d =
                first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]");
            if (!d.empty()) return d;
        }
        if (a.size() != b.size())
            return here + " (" + std::to_string(a.size()) + " / " + std::to_string(b.size()) +
                   " entries)";
        return "";
    }
    if (a != b) return here + " (" + a.dump() + " / " + b.dump() + ")";
    return "";
}

int check_firmware(const std::string& binary, const std::string& path) {
    std::string error;
    std::unique_ptr<firmware::plugin> plugin;
    if (!path.empty() && !(plugin = firmware::plugin::load(path, &error))) {
        print_error(error);
        return exit_bad_input;
    }
    const stereosim_fw_descriptor& d =
        plugin ? plugin->descriptor() : firmware::builtin();
    std::string pattern = (fs::temp_directory_path() / "stereosim-check-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
        print_error("cannot create a folder for the check's runs in " +
                    fs::temp_directory_path().string());
        return exit_run_failed;
    }
    const fs::path dir = pattern;
    const std::string frames = std::to_string(check_frames);
    const std::vector<std::vector<std::string>> commands = {
        with_firmware({binary, "run", "--quiet", "--frames", frames, "--out", dir / "a"}, path),
        with_firmware({binary, "run", "--quiet", "--frames", frames, "--out", dir / "b"}, path),
        with_firmware({binary, "faults", "--campaign", "smoke", "--match", forked_rows,
                       "--keep-runs", "--jobs", "1", "--out", dir / "forked"},
                      path),
        with_firmware({binary, "faults", "--campaign", "smoke", "--match", forked_rows,
                       "--keep-runs", "--no-snapshots", "--jobs", "1", "--out", dir / "fresh"},
                      path)};
    std::printf("firmware check: %s %s\n", d.name, d.version);
    int rc = 0;
    std::string difference;
    if (!run_all(commands, dir, &error)) {
        std::fflush(stdout);
        print_error(error);
        rc = exit_run_failed;
    } else if (!(difference = compare_runs(dir / "a", dir / "b")).empty()) {
        difference = "the default scenario run twice differs first at " + difference;
    } else {
        std::printf(
            "  the default scenario twice (%d frames): the same report.json and "
            "frames.csv\n",
            check_frames);
        for (const fs::directory_entry& run : fs::directory_iterator(dir / "forked" / "runs")) {
            const fs::path twin = dir / "fresh" / "runs" / run.path().filename() / "out";
            difference = compare_runs(run.path() / "out", twin);
            if (!difference.empty()) {
                difference =
                    "a fault run forked from a snapshot differs from its run from the "
                    "start first at " +
                    difference;
                break;
            }
        }
        if (difference.empty()) {
            int rows = 0, forked = 0;
            try {
                const json campaign = json::parse(read_text(dir / "forked" / "campaign.json"));
                for (const json& row : campaign.at("rows")) {
                    ++rows;
                    forked += row.value("snapshot_ms", json()).is_number();
                }
            } catch (const std::exception&) {
            }
            std::printf(
                "  %d fault runs (%s), %d of them forked from a snapshot, against their "
                "runs from the start: the same\n",
                rows, forked_rows, forked);
        }
    }
    std::fflush(stdout);  // what was compared, before the verdict
    if (!difference.empty()) {
        print_error("firmware '" + std::string(d.name) + "' is not deterministic: " + difference);
        rc = 1;
    } else if (rc == 0) {
        std::printf("deterministic: yes\n");
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    return rc;
}

}  // namespace cli
