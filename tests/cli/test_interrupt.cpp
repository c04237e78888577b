// A campaign or a sweep that gets SIGTERM (a Slurm time limit) or SIGINT
// (Ctrl-C) while its runs are under way (docs/cli.md, "Interrupted runs"):
// its children stop with it, what finished is written and marked
// incomplete, the exit status is 128 + the signal, and --resume DIR runs only
// what is missing, to the same result as a run that was never interrupted.
#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tb/app/cli/host_figures.h"

namespace {

namespace fs = std::filesystem;
using cli::without_host_figures;
using nlohmann::json;

// stereosim with `args`, its stdout and stderr into one pipe.
struct child {
    pid_t pid = -1;
    int output = -1;
    std::string seen;
};

child start(const std::vector<std::string>& args) {
    child c;
    int fds[2];
    if (pipe(fds) != 0) return c;
    c.pid = fork();
    if (c.pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        std::vector<char*> argv;
        std::vector<std::string> all = {STEREOSIM_BINARY};
        all.insert(all.end(), args.begin(), args.end());
        for (std::string& a : all) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(STEREOSIM_BINARY, argv.data());
        _exit(127);
    }
    close(fds[1]);
    c.output = fds[0];
    return c;
}

// How long a first run may take to finish: an 8-frame run takes ~5 s, and
// took over 120 s under AddressSanitizer beside another build on 2 cores (a
// bound on the wait, not a timing check).
constexpr double first_result_s = 400;

// Reads the child's output until `text` shows or `seconds` pass.
bool wait_for(child& c, const std::string& text, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    char buf[4096];
    while (c.seen.find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > end) return false;
        pollfd p{c.output, POLLIN, 0};
        if (poll(&p, 1, 200) <= 0) continue;
        const ssize_t n = read(c.output, buf, sizeof buf);
        if (n <= 0) return false;
        c.seen.append(buf, static_cast<size_t>(n));
    }
    return true;
}

int finish(child& c) {
    char buf[4096];
    for (ssize_t n; (n = read(c.output, buf, sizeof buf)) > 0;) c.seen.append(buf, n);
    close(c.output);
    int status = 0;
    waitpid(c.pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Processes whose command line names `dir`: a run left behind. A stopped
// child's /proc entry may linger a moment after its parent reaped it.
int processes_naming(const std::string& dir) {
    const auto count = [&] {
        int found = 0;
        DIR* proc = opendir("/proc");
        for (dirent* e; proc && (e = readdir(proc)) != nullptr;) {
            if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
            std::ifstream in(std::string("/proc/") + e->d_name + "/cmdline");
            std::string cmdline((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
            found += cmdline.find(dir) != std::string::npos;
        }
        if (proc) closedir(proc);
        return found;
    };
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    int found = count();
    while (found > 0 && std::chrono::steady_clock::now() < end) {
        usleep(100000);
        found = count();
    }
    return found;
}

json read_json(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

fs::path scratch(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("stereosim_test_interrupt_" + std::to_string(getpid())) / name;
    fs::remove_all(dir);
    return dir;
}

// Three smoke runs of 8 frames, two of them forked from one snapshot leader:
// stopped after the first finished, resumed, and run whole for comparison.
TEST(Interrupt, ACampaignStopsItsRunsAndResumes) {
    const std::vector<std::string> slice = {
        "faults",
        "--campaign",
        "smoke",
        "--jobs",
        "1",
        "--match",
        "dark-leak:sensor=L,level=8|skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@frame=4"};
    const fs::path cut = scratch("cut"), whole = scratch("whole");
    std::vector<std::string> args = slice;
    args.insert(args.end(), {"--out", cut.string()});
    child c = start(args);
    ASSERT_GT(c.pid, 0);
    ASSERT_TRUE(wait_for(c, "[1/3]", first_result_s)) << c.seen;
    kill(c.pid, SIGTERM);
    EXPECT_EQ(finish(c), 128 + SIGTERM) << c.seen;
    EXPECT_EQ(processes_naming(cut.string()), 0) << "a run outlived its campaign";
    EXPECT_NE(c.seen.find("interrupted by SIGTERM"), std::string::npos) << c.seen;
    const json partial = read_json(cut / "campaign.json");
    EXPECT_FALSE(partial["complete"].get<bool>());
    EXPECT_EQ(partial["interrupted_by"], "SIGTERM");
    ASSERT_GE(partial["rows"].size(), 1u);
    ASSERT_LT(partial["rows"].size(), 3u);

    child r = start({"faults", "--campaign", "smoke", "--jobs", "1", "--match", slice.back(),
                     "--resume", cut.string()});
    ASSERT_GT(r.pid, 0);
    EXPECT_EQ(finish(r), 0) << r.seen;
    EXPECT_NE(r.seen.find("[" + std::to_string(3 - partial["rows"].size()) + "/" +
                          std::to_string(3 - partial["rows"].size()) + "]"),
              std::string::npos)
        << "the resumed campaign ran more than the missing runs:\n"
        << r.seen;
    args = slice;
    args.insert(args.end(), {"--out", whole.string()});
    child w = start(args);
    ASSERT_GT(w.pid, 0);
    EXPECT_EQ(finish(w), 0) << w.seen;
    const json resumed = read_json(cut / "campaign.json"),
               uncut = read_json(whole / "campaign.json");
    EXPECT_TRUE(resumed["complete"].get<bool>());
    EXPECT_EQ(without_host_figures(resumed["rows"]), without_host_figures(uncut["rows"]));
    EXPECT_EQ(resumed["contract_broken"], uncut["contract_broken"]);
    fs::remove_all(cut.parent_path());
}

// A sweep of three points of 4 frames, one point at a time.
TEST(Interrupt, ASweepStopsItsPointsAndResumes) {
    const std::vector<std::string> sweep = {
        "sweep", "--grid", "firmware.search_radius=8,16,24", "--frames", "4", "--jobs", "1"};
    const fs::path cut = scratch("sweep-cut"), whole = scratch("sweep-whole");
    std::vector<std::string> args = sweep;
    args.insert(args.end(), {"--out", cut.string()});
    child c = start(args);
    ASSERT_GT(c.pid, 0);
    ASSERT_TRUE(wait_for(c, "sweep: 1/3 points", first_result_s)) << c.seen;
    kill(c.pid, SIGINT);
    EXPECT_EQ(finish(c), 128 + SIGINT) << c.seen;
    EXPECT_EQ(processes_naming(cut.string()), 0) << "a point outlived its sweep";
    const json partial = read_json(cut / "sweep.json");
    EXPECT_FALSE(partial["complete"].get<bool>());
    int ran = 0;
    for (const json& p : partial["points"]) ran += p.value("ran", false);
    ASSERT_GE(ran, 1);
    ASSERT_LT(ran, 3);

    args = sweep;
    args.insert(args.end(), {"--resume", cut.string()});
    child r = start(args);
    ASSERT_GT(r.pid, 0);
    EXPECT_EQ(finish(r), 0) << r.seen;
    EXPECT_NE(r.seen.find("sweep: " + std::to_string(3 - ran) + "/" + std::to_string(3 - ran) +
                          " points"),
              std::string::npos)
        << r.seen;
    args = sweep;
    args.insert(args.end(), {"--out", whole.string()});
    child w = start(args);
    ASSERT_GT(w.pid, 0);
    EXPECT_EQ(finish(w), 0) << w.seen;
    const json resumed = read_json(cut / "sweep.json"), uncut = read_json(whole / "sweep.json");
    EXPECT_TRUE(resumed["complete"].get<bool>());
    EXPECT_EQ(without_host_figures(resumed["points"]), without_host_figures(uncut["points"]));
    EXPECT_EQ(without_host_figures(resumed["summary"]), without_host_figures(uncut["summary"]));
    fs::remove_all(cut.parent_path());
}

}  // namespace
