#include "tb/app/faults/snapshots.h"
#include "tb/platform/firmware_crash.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <numeric>

#include "model/time/sc_ticks.h"
#include "tb/app/cli/interrupt.h"
#include "tb/app/cli/run_command.h"
#include "tb/app/faults/child_exit.h"
#include "tb/app/faults/job_tokens.h"
#include "tb/platform/platform.h"

namespace faults {

namespace {

constexpr simtime::ticks ticks_per_ms = 1000000 * simtime::ticks_per_ns;

// One `stereosim run` parsed into its own run command and extensions.
struct parsed_run {
    CLI::App app;
    std::unique_ptr<cli::run_command> run;
};

bool parse_run(const std::vector<std::string>& args, const extensions_factory& make,
               parsed_run* out) {
    out->run = std::make_unique<cli::run_command>(out->app, make());
    std::vector<std::string> text = {"stereosim", "run"};
    text.insert(text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : text) argv.push_back(a.data());
    try {
        out->app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        cli::print_error(e.what());
        return false;
    }
    return true;
}

std::vector<std::string> without_faults(const std::vector<std::string>& args) {
    std::vector<std::string> out;
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--fault") {
            ++i;  // and its spec
            continue;
        }
        out.push_back(args[i]);
    }
    return out;
}

// This process's output into `path`, as a spawned run's log.txt.
void redirect_output(const std::string& path) {
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return;
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
}

enum class due { not_yet, now, missed };

// At a pause at `now`: whether the member's snapshot must be taken now
// (the next pause could be too late) or was missed.
due snapshot_due(const snapshot_trigger& t, const platform::platform_top& top, simtime::ticks now) {
    bool take = false;
    if (t.before_tick >= 0) {
        if (now > t.before_tick) return due::missed;
        take = now + snapshot_pause_step > t.before_tick;
    }
    for (const snapshot_trigger::sensor_frame& f : t.frames) {
        const auto& truth = top.cycle_island().sensor(f.camera).truth();
        const int64_t current = truth.empty() ? -1 : static_cast<int64_t>(truth.back().index);
        if (current >= static_cast<int64_t>(f.frame)) return due::missed;
        take = take || current + 1 >= static_cast<int64_t>(f.frame);
    }
    if (take && t.cpu_slow_tick >= 0) {
        // A charge in flight across the onset would run unslowed in the
        // child: run from the start instead (standalone, it is slowed).
        const sc_core::sc_time charge_end = top.cpu().charge_end();
        if (charge_end > simtime::sc_time_of(t.cpu_slow_tick)) return due::missed;
    }
    return take ? due::now : due::not_yet;
}

// The member's run in a child: from the paused platform (its faults added),
// or, where its snapshot was missed, from the start by exec of `binary`.
// The child first takes a job token; its leader puts it back (reap_one).
pid_t fork_member(const snapshot_member& m, platform::platform_top* top, const std::string& binary,
                  const extensions_factory& make, const job_tokens& tokens) {
    std::fflush(nullptr);
    const pid_t pid = cli::fork_untied();
    if (pid != 0) return pid;
    tokens.take();
    redirect_output(m.dir + "/log.txt");
    if (top) {
        parsed_run run;
        const int rc = parse_run(m.args, make, &run) ? run.run->execute_from_snapshot(*top)
                                                     : cli::exit_bad_input;
        std::fflush(nullptr);
        exit_child(rc);
    }
    std::vector<std::string> text = {binary, "run"};
    text.insert(text.end(), m.args.begin(), m.args.end());
    std::vector<char*> argv;
    for (std::string& a : text) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
}

// The members' children, each forked the moment its snapshot is due (the
// leader never waits to take one); a child computes once it holds a job
// token, which the leader puts back as it reaps the child. Each child's
// DIR/status is written as it ends.
class member_children {
  public:
    explicit member_children(const job_tokens& tokens) : m_tokens(tokens) {}

    // snapshot_ms: the simulated time of its snapshot, -1 when from the start.
    void start(const snapshot_member& m, platform::platform_top* top, double snapshot_ms,
               const std::string& binary, const extensions_factory& make) {
        const auto t0 = std::chrono::steady_clock::now();
        const pid_t pid = fork_member(m, top, binary, make, m_tokens);
        if (pid < 0) {
            write_status(m.dir, cli::exit_run_failed << 8, 0.0, -1.0);  // as if it exited 3
            return;
        }
        m_running.push_back({pid, m.dir, t0, snapshot_ms});
    }
    void wait_all() {
        while (!m_running.empty()) reap_one();
    }

  private:
    struct child {
        pid_t pid;
        std::string dir;
        std::chrono::steady_clock::time_point started;
        double snapshot_ms;
    };
    static void write_status(const std::string& dir, int status, double wall, double snapshot_ms) {
        std::ofstream(dir + "/status") << status << ' ' << wall << ' ' << snapshot_ms << '\n';
    }
    void reap_one() {
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            for (const child& c : m_running)
                write_status(c.dir, cli::exit_run_failed << 8, 0.0, c.snapshot_ms);
            m_running.clear();
            return;
        }
        for (auto it = m_running.begin(); it != m_running.end(); ++it) {
            if (it->pid != pid) continue;
            const std::chrono::duration<double> wall =
                std::chrono::steady_clock::now() - it->started;
            write_status(it->dir, status, wall.count(), it->snapshot_ms);
            m_running.erase(it);
            m_tokens.put();
            return;
        }
    }
    job_tokens m_tokens;
    std::vector<child> m_running;
};

}  // namespace

namespace {

// The leader's fault-free run: forks each member at its snapshot (or from
// the start where it was missed); returns the leader's exit code.
int fork_at_snapshots(const std::vector<snapshot_member>& members, const std::string& binary,
                      const extensions_factory& make_extensions, member_children& children) {
    if (members.empty()) return 0;
    parsed_run base;
    cli::run_setup setup;
    platform::platform_config config;
    std::string error;
    if (!parse_run(without_faults(members[0].args), make_extensions, &base))
        return cli::exit_bad_input;
    if (!base.run->prepare(&setup, &config, &error)) {
        cli::print_error(error);
        return cli::exit_bad_input;
    }
    std::vector<size_t> pending(members.size());
    std::iota(pending.begin(), pending.end(), size_t{0});
    try {
        platform::platform_top top(config);
        const simtime::ticks end = config.period * config.frames;
        for (simtime::ticks now = 0;;) {
            for (auto it = pending.begin(); it != pending.end();) {
                const due d =
                    now >= end ? due::missed : snapshot_due(members[*it].trigger, top, now);
                if (d == due::not_yet) {
                    ++it;
                    continue;
                }
                // The leader's log says which way each member ran.
                const bool forked = d == due::now;
                const double at_ms = static_cast<double>(now) / ticks_per_ms;
                if (forked)
                    std::printf("snapshot at %.3f ms: %s\n", at_ms, members[*it].dir.c_str());
                else
                    std::printf("snapshot missed, from the start: %s\n", members[*it].dir.c_str());
                children.start(members[*it], forked ? &top : nullptr, forked ? at_ms : -1.0, binary,
                               make_extensions);
                it = pending.erase(it);
            }
            if (pending.empty()) return 0;
            now = std::min(end, now + snapshot_pause_step);
            top.run_until(now);
        }
    } catch (const std::exception& e) {
        cli::print_error(std::string("the snapshot's fault-free run failed: ") + e.what());
        for (size_t i : pending) children.start(members[i], nullptr, -1.0, binary, make_extensions);
        return cli::exit_run_failed;
    }
}

}  // namespace

int run_snapshot_group(const std::vector<snapshot_member>& members, const std::string& binary,
                       const extensions_factory& make_extensions, const std::string& leader_log,
                       const job_tokens& tokens) {
    redirect_output(leader_log);
    platform::install_firmware_crash_report();  // the forked members keep it
    member_children children(tokens);
    const int rc = fork_at_snapshots(members, binary, make_extensions, children);
    tokens.put();  // the leader's own token: it stops computing
    children.wait_all();
    return rc;
}

}  // namespace faults
