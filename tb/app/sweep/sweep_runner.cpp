#include "tb/app/sweep/sweep_runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include "tb/app/cli/child_run.h"
#include "tb/app/cli/interrupt.h"
#include "tb/app/sweep/sweep_grid.h"
#include "tb/app/sweep/sweep_point.h"

namespace sweep {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

std::string point_dir(const run_request& r, const json& point) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu", point.at("index").get<size_t>());
    return r.out_dir + "/points/" + name;
}

pid_t spawn_point(const run_request& r, const json& point, const std::string& dir,
                  std::string* error) {
    std::vector<std::string> args = {r.binary, "run", "--quiet"};
    if (!r.config_file.empty()) args.insert(args.end(), {"--config", r.config_file});
    for (const std::string& s : r.base_sets) args.insert(args.end(), {"--set", s});
    for (const auto& [key, value] : point.at("keys").items())
        args.insert(args.end(), {"--set", key + "=" + value_text(value)});
    args.insert(args.end(), {"--out", dir + "/out"});
    return cli::spawn_logged(args, dir + "/log.txt", error);
}

// The finished child's point: its figures, or why it has none.
bool collect(const run_request& r, json& point, const std::string& dir, int status) {
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    point["exit_code"] = code;
    std::ifstream in(dir + "/out/report.json");
    std::string error;
    bool ok = false;
    if ((code == 0 || code == 1) && in) {
        try {
            ok = read_point_report(json::parse(in), &point, &error);
        } catch (const std::exception& e) {
            error = std::string("unreadable report.json: ") + e.what();
        }
    } else {
        const std::string last = cli::last_line_of(dir + "/log.txt");
        error = "exit " + std::to_string(code) + (last.empty() ? "" : ": " + last);
    }
    if (!ok) point["error"] = error;
    point["ran"] = ok;
    mark_agreement(&point);
    std::error_code ec;
    if (ok && !r.keep_runs) fs::remove_all(dir, ec);
    return ok;
}

void progress(std::FILE* log, size_t done, size_t total, int over, int failed,
              clock_type::time_point t0) {
    if (!log) return;
    const double elapsed = std::chrono::duration<double>(clock_type::now() - t0).count();
    const double eta =
        done ? elapsed / static_cast<double>(done) * static_cast<double>(total - done) : 0;
    std::fprintf(log,
                 "sweep: %zu/%zu points, %d over budget, %d failed, %.0f s elapsed, ETA %.0f s%s",
                 done, total, over, failed, elapsed, eta, isatty(fileno(log)) ? "\r" : "\n");
    if (done == total && isatty(fileno(log))) std::fputc('\n', log);
    std::fflush(log);
}

}  // namespace

std::string this_program() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("stereosim") : p.string();
}

int run_points(const run_request& request, std::vector<json>& points, std::FILE* log,
               int* interrupted) {
    std::vector<size_t> todo;
    for (size_t i = 0; i < points.size(); ++i)
        if (points[i].value("simulate", false) && !points[i].value("ran", false)) todo.push_back(i);
    const cli::interrupt_catcher interrupt;
    std::map<pid_t, std::pair<size_t, clock_type::time_point>> running;
    size_t next = 0, done = 0;
    int failed = 0, over = 0;
    const auto t0 = clock_type::now();
    while ((next < todo.size() || !running.empty()) && !interrupt.caught()) {
        while (next < todo.size() && static_cast<int>(running.size()) < request.jobs) {
            json& point = points[todo[next++]];
            const std::string dir = point_dir(request, point);
            std::error_code ec;
            fs::create_directories(dir, ec);
            std::string error = ec ? "cannot create " + dir + ": " + ec.message() : "";
            const pid_t pid = error.empty() ? spawn_point(request, point, dir, &error) : -1;
            if (pid < 0) {
                point["ran"] = false;
                point["error"] = error;
                ++failed;
                ++done;
                continue;
            }
            running[pid] = {todo[next - 1], clock_type::now()};
        }
        if (running.empty()) continue;
        int status = 0;
        const pid_t pid = cli::wait_child(interrupt, &status);
        if (pid == 0) break;  // an interrupt
        if (pid < 0) {        // no child left to wait for: the points under way are lost
            for (const auto& [lost, started] : running) {
                points[started.first]["ran"] = false;
                points[started.first]["error"] = "its process could not be waited for";
            }
            failed += static_cast<int>(running.size());
            running.clear();
            continue;
        }
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        json& point = points[it->second.first];
        point["wall_s"] =
            std::chrono::duration<double>(clock_type::now() - it->second.second).count();
        if (!collect(request, point, point_dir(request, point), status))
            ++failed;
        else if (point["verdict"] == "over")
            ++over;
        running.erase(it);
        progress(log, ++done, todo.size(), over, failed, t0);
    }
    // Interrupted: the points under way stop and are not counted.
    std::vector<pid_t> pids;
    for (const auto& [pid, started] : running) {
        pids.push_back(pid);
        points[started.first].erase("ran");
    }
    cli::stop_children(pids);
    if (interrupted) *interrupted = interrupt.caught();
    return failed;
}

}  // namespace sweep
