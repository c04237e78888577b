#include "tb/app/faults/campaign.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <unistd.h>
#include <csignal>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include "tb/app/cli/child_run.h"
#include "tb/app/cli/firmware_identity.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/interrupt.h"
#include "tb/app/cli/run_command.h"
#include "tb/app/faults/campaign_files.h"
#include "tb/app/faults/child_exit.h"
#include "tb/firmware/builtin.h"
#include "tb/firmware/plugin.h"
#include "tb/platform/firmware_crash.h"
#include "tb/platform/platform_config.h"

namespace faults {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string this_program() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("stereosim") : p.string();
}

// One child: `binary run ...`, output to the run's folder.
// The `stereosim run` options of a campaign run (after "run").
std::vector<std::string> run_args(const campaign_run& r, const std::string& dir,
                                  const campaign_options& o) {
    std::vector<std::string> args = {"--quiet",
                                     "--frames",
                                     std::to_string(r.frames),
                                     "--seed",
                                     std::to_string(r.seed),
                                     "--card-retry-limit",
                                     std::to_string(r.retry_limit),
                                     "--out",
                                     dir + "/out"};
    for (const std::string& spec : spec_words(r.fault)) {
        args.push_back("--fault");
        args.push_back(spec);
    }
    for (const std::string& setting : r.settings) {
        args.push_back("--set");
        args.push_back(setting);
    }
    if (!o.firmware.empty()) {
        args.push_back("--firmware");
        args.push_back(o.firmware);
    }
    if (o.paper_card) args.push_back("--paper-card");
    return args;
}

pid_t spawn_run(const campaign_options& o, const campaign_run& r, const std::string& dir,
                std::string* error) {
    std::vector<std::string> args = {o.binary, "run"};
    for (std::string& a : run_args(r, dir, o)) args.push_back(std::move(a));
    return cli::spawn_logged(args, dir + "/log.txt", error);
}

void collect(campaign_row& row, const std::string& dir, int status) {
    row.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::ifstream in(dir + "/out/report.json");
    if (!in) {
        const std::string last = cli::last_line_of(dir + "/log.txt");
        row.error = "exit " + std::to_string(row.exit_code) + ", no report.json" +
                    (last.empty() ? "" : ": " + last);
        row.crashed =
            row.exit_code == cli::exit_run_failed && platform::is_firmware_failure_line(last);
        return;
    }
    try {
        const json report = json::parse(in);
        std::string error;
        if (!read_from_report(report, &row.result, &error)) {
            row.error = error;
            return;
        }
        row.ran = true;
        if (report.value("not_judged", json()).is_string()) {
            const std::string text = report["not_judged"].get<std::string>();
            const std::string prefix = "not judged: ";
            row.not_judged = text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
        }
        for (const verdict& v : row.result.verdicts)
            for (const std::string& why : v.not_judged)
                row.not_judged += (row.not_judged.empty() ? "" : "; ") + why;
    } catch (const std::exception& e) {
        row.error = std::string("unreadable report.json: ") + e.what();
    }
}

json row_json(const campaign_row& r) {
    json j = {{"index", r.run.index},
              {"fault", r.run.fault.empty() ? "clean" : r.run.fault},
              {"seed", r.run.seed},
              {"frames", r.run.frames},
              {"retry_limit", r.run.retry_limit},
              {"settings", r.run.settings},
              {"ran", r.ran},
              {"exit_code", r.exit_code},
              {"wall_s", r.wall_s},
              {"snapshot_ms", r.snapshot_ms >= 0 ? json(r.snapshot_ms) : json(nullptr)},
              {"contract_ok", r.ok()}};
    if (!r.ran) {
        j["error"] = r.error;
        if (r.crashed) j["actual"] = "crash";
        return j;
    }
    const run_observation& run = r.result.run;
    const verdict& v = r.result.verdicts.front();
    j["kind"] = r.result.specs.empty() ? "clean" : fault_type_name(r.result.specs[0].type);
    j["expected"] = v.expected_text;
    j["actual"] = outcome_name(v.actual);
    if (!run.faults.empty()) {
        const fault_observation& f = run.faults[0];
        j["onset_ms"] = f.in_effect ? json(f.onset_ms) : json(nullptr);
        j["detected_by"] = f.detected_by;
        j["reported_by"] = f.reported_by;
        j["verdict_causes"] = f.causes;
        j["frames_to_detect"] = f.detected ? json(f.frames_to_detect) : json(nullptr);
        j["frames_to_recover"] = f.recovered ? json(f.frames_to_recover) : json(nullptr);
        j["failed_starts"] = f.failed_starts;
        j["pairs_discarded"] = f.pairs_discarded;
        j["pairs_used_after_onset"] = f.pairs_used;
        j["pairs_dropped_after_onset"] = f.pairs_dropped;
    } else {
        j["pairs_discarded"] = run.card_sync_errors + run.card_overflows;
    }
    j["unsynced_pairs_used"] = run.unsynced_pairs_used;
    j["misses"] = run.misses;
    j["false_alarms"] = run.false_alarms;
    j["sync_errors"] = run.card_sync_errors;
    j["pairs_forwarded"] = run.pairs_forwarded;
    j["pairs_in_step"] = run.pairs_in_step;
    j["pairs_processed"] = run.pairs_processed;
    j["pairs_dropped"] = run.pairs_dropped;
    j["pairs_unaccounted"] = run.pairs_unaccounted;
    j["unreported_sync_errors"] = run.unreported_sync_errors;
    j["unreported_overflows"] = run.unreported_overflows;
    j["identity_checked"] = run.identity_checked;
    j["identity_mismatches"] = run.identity_mismatches;
    j["hard_error_ms"] = run.hard_error ? json(run.hard_error_ms) : json(nullptr);
    json violations = json::array();
    for (const verdict& x : r.result.verdicts)
        for (const std::string& s : x.violations) violations.push_back(s);
    j["violations"] = violations;
    j["mode"] = run.mode;
    j["dsk"] = run.dsk_version;
    j["not_judged"] = r.not_judged.empty() ? json(nullptr) : json(r.not_judged);
    json faults = json::array();
    for (size_t i = 0; i < r.result.specs.size() && i < run.faults.size(); ++i) {
        const fault_spec& s = r.result.specs[i];
        const outcome o = r.result.verdicts[i].actual;
        faults.push_back({{"spec", run.faults[i].spec},
                          {"kind", fault_type_name(s.type)},
                          {"sensor", is_sensor_fault(s.type) ? (s.camera == 0 ? "L" : "R") : "-"},
                          {"outcome", outcome_name(o)},
                          {"safety_class", safety_class(s.type, o)},
                          {"onset_phases", run.faults[i].onset_phases}});
    }
    j["faults"] = faults;
    return j;
}

// The shard's runs whose spec matches --match A|B (contains A or B).
std::vector<campaign_run> selected_runs(const campaign_options& o) {
    std::vector<campaign_run> plan;
    // The firmware under test's keys, read once (the command checked it loads).
    std::string error;
    const std::unique_ptr<firmware::plugin> plugin =
        o.firmware.empty() ? nullptr : firmware::plugin::load(o.firmware, &error);
    const stereosim_fw_descriptor& under_test = plugin ? plugin->descriptor() : firmware::builtin();
    for (campaign_run r : shard_of(campaign_plan(o.name, o.seeds), o.shard, o.shards)) {
        r.settings = cli::settings_it_takes(r.settings, under_test);
        const std::string spec = r.fault.empty() ? "clean" : r.fault;
        bool hit = false;
        for (size_t from = 0; from <= o.match.size();) {
            const size_t bar = std::min(o.match.find('|', from), o.match.size());
            hit |= spec.find(o.match.substr(from, bar - from)) != std::string::npos;
            from = bar + 1;
        }
        if (hit) plan.push_back(r);
    }
    return plan;
}

void log_row(std::FILE* log, size_t done, size_t total, const campaign_row& row) {
    std::fprintf(log, "[%zu/%zu] %-45s seed %-4llu %s%s (%.1f s)\n", done, total,
                 row.run.fault.empty() ? "clean" : row.run.fault.c_str(),
                 static_cast<unsigned long long>(row.run.seed),
                 row.ran ? outcome_name(row.result.verdicts.front().actual) : "NOT RUN",
                 row.ok() ? "" : "  CONTRACT BROKEN", row.wall_s);
    std::fflush(log);
}

std::vector<fault_spec> specs_of(const campaign_run& r) {
    std::vector<fault_spec> specs;
    std::string error;
    for (const std::string& text : spec_words(r.fault)) {
        const std::optional<fault_spec> spec = parse_fault_spec(text, &error);
        if (!spec) return {};
        specs.push_back(*spec);
    }
    return specs;
}

// What the campaign starts as one child process: a run, or a group of runs
// forked from one fault-free run at their snapshots (snapshots.h).
struct unit {
    std::vector<size_t> runs;  // plan indices
    bool group = false;
};

// Runs of one seed, length, RETRY_LIMIT and settings whose faults all start
// later form a group; the rest run alone.
std::vector<unit> units_of(const campaign_options& o, const std::vector<campaign_run>& plan) {
    const bool snapshots = o.snapshots && o.run_group && o.binary == this_program();
    const simtime::ticks period = platform::platform_config{}.period;
    std::vector<unit> units;
    std::map<std::string, size_t> group_of;
    for (size_t i = 0; i < plan.size(); ++i) {
        const campaign_run& r = plan[i];
        if (!snapshots || !snapshot_trigger_of(specs_of(r), period).usable) {
            units.push_back({{i}, false});
            continue;
        }
        std::string key = std::to_string(r.seed) + ' ' + std::to_string(r.frames) + ' ' +
                          std::to_string(r.retry_limit);
        for (const std::string& setting : r.settings) key += ' ' + setting;
        const auto [it, added] = group_of.emplace(key, units.size());
        if (added) units.push_back({{}, true});
        units[it->second].runs.push_back(i);
    }
    for (unit& u : units) u.group = u.group && u.runs.size() > 1;
    return units;
}

// Forks the leader of a snapshot group (it holds the job token the caller
// took); -1 and *error if it cannot.
pid_t start_group(const campaign_options& o, const std::vector<campaign_run>& plan, const unit& u,
                  const std::function<std::string(size_t)>& run_dir, const job_tokens& tokens,
                  std::string* error) {
    const simtime::ticks period = platform::platform_config{}.period;
    std::vector<snapshot_member> members;
    for (size_t i : u.runs)
        members.push_back({run_args(plan[i], run_dir(i), o), run_dir(i),
                           snapshot_trigger_of(specs_of(plan[i]), period)});
    std::fflush(nullptr);
    const pid_t pid = cli::fork_untied();
    if (pid == 0) {
        exit_child(o.run_group(members, o.binary, run_dir(u.runs[0]) + "/leader.txt", tokens));
    }
    if (pid < 0) *error = std::string("cannot fork a snapshot group: ") + std::strerror(errno);
    return pid;
}

// A group member's wait status and wall time as its leader wrote them; the
// leader's own status if it wrote none.
int member_status(const std::string& dir, int leader_status, double* wall, double* snapshot_ms) {
    std::ifstream in(dir + "/status");
    int status = 0;
    if (in >> status >> *wall >> *snapshot_ms) return status;
    *wall = 0;
    *snapshot_ms = -1;
    return leader_status != 0 ? leader_status : 3 << 8;  // as if the run had exited 3
}

// Runs the plan, each run in its own folder under runs/, at most o.jobs
// processes computing at a time (job_tokens.h: a spawned run holds a token
// until it is reaped, a snapshot group's leader until its fault-free run
// ends, each of its forked runs while it runs); fills rows[i] as run i ends.
// An interrupt stops the runs under way: rows[i].finished stays false.
class plan_runner {
  public:
    plan_runner(const campaign_options& o, const std::vector<campaign_run>& plan,
                std::vector<campaign_row>& rows, std::FILE* log)
        : m_o(o),
          m_plan(plan),
          m_rows(rows),
          m_log(log),
          m_units(units_of(o, plan)),
          m_tokens(job_tokens::make(o.jobs)),
          m_started(m_units.size()) {}

    void run(const cli::interrupt_catcher& interrupt) {
        if (!m_tokens.valid()) {
            for (campaign_row& row : m_rows) {
                row.error = "cannot create the job pipe";
                row.finished = true;
            }
            return;
        }
        while (m_done < m_plan.size() && !interrupt.caught() && m_broken < 0) {
            start_units();
            if (!m_running.empty() && !reap_one()) break;
        }
        if (interrupt.caught() || m_broken >= 0) stop();
        m_tokens.close_fds();
    }

  private:
    std::string run_dir(size_t i) const {
        return m_o.out_dir + "/runs/" + std::to_string(m_plan[i].index);
    }

    void finish(size_t i, int status, double wall) {
        campaign_row& row = m_rows[i];
        row.finished = true;
        row.wall_s = wall;
        collect(row, run_dir(i), status);
        std::error_code ec;
        if (!m_o.keep_runs && row.ran) fs::remove_all(run_dir(i), ec);
        ++m_done;
        if (m_log) log_row(m_log, m_done, m_plan.size(), row);
        if (m_o.stop_on_violation && !row.ok() && m_broken < 0) m_broken = row.run.index;
    }

    // The line of a group leader's firmware crash or hang ("" if none).
    std::string leader_failure(const unit& u) const {
        const std::string line = cli::last_line_of(run_dir(u.runs[0]) + "/leader.txt");
        return platform::is_firmware_failure_line(line) ? line : std::string();
    }

  public:
    // The plan index of the run that stopped the campaign, -1 if none did.
    int broken() const { return m_broken; }

  private:
    // A group's runs as their leader's child statuses say.
    void finish_group(const unit& u, int leader_status) {
        // A leader whose firmware crashed or hung in the fault-free prefix:
        // the runs it had not forked yet end as it did, with its line.
        const std::string leader_line = leader_failure(u);
        for (size_t i : u.runs) {
            if (!leader_line.empty() && !fs::exists(run_dir(i) + "/status"))
                std::ofstream(run_dir(i) + "/log.txt", std::ios::app) << leader_line << "\n";
            double wall = 0;
            const int status =
                member_status(run_dir(i), leader_status, &wall, &m_rows[i].snapshot_ms);
            finish(i, status, wall);
        }
    }

    // Starts the units a free job token allows.
    void start_units() {
        std::error_code ec;
        while (m_next < m_units.size() && m_tokens.try_take()) {
            const unit& u = m_units[m_next];
            for (size_t i : u.runs) {
                m_rows[i].run = m_plan[i];
                fs::remove_all(run_dir(i), ec);
                fs::create_directories(run_dir(i), ec);
            }
            std::string error;
            const std::function<std::string(size_t)> dir = [this](size_t i) { return run_dir(i); };
            const pid_t pid = u.group ? start_group(m_o, m_plan, u, dir, m_tokens, &error)
                                      : spawn_run(m_o, m_plan[u.runs[0]], dir(u.runs[0]), &error);
            if (pid < 0) {
                m_tokens.put();
                for (size_t i : u.runs) {
                    m_rows[i].error = error;
                    m_rows[i].finished = true;
                }
                m_done += u.runs.size();
            } else {
                m_running[pid] = m_next;
                m_started[m_next] = std::chrono::steady_clock::now();
            }
            ++m_next;
        }
    }

    // With runs still to start, looks for a free token now and then (a
    // group's leader or forked run frees one without the campaign reaping
    // anything); polls, so that an interrupt is never missed in a blocking
    // wait. False when nothing can be waited for.
    bool reap_one() {
        int status = 0;
        const pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid == 0) {
            if (m_next < m_units.size())
                m_tokens.wait_free(100);
            else
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            return true;
        }
        if (pid < 0) return errno == EINTR;  // an interrupt is looked at by the caller
        const auto it = m_running.find(pid);
        if (it == m_running.end()) return true;
        const unit& u = m_units[it->second];
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started[it->second])
                .count();
        m_running.erase(it);
        // A run's token comes back here; a leader gave its own back unless it
        // was killed or its firmware ended it (the crash report's _exit).
        const bool leader_failed = u.group && WIFEXITED(status) &&
                                   WEXITSTATUS(status) == cli::exit_run_failed &&
                                   !leader_failure(u).empty();
        if (!u.group || WIFSIGNALED(status) || leader_failed) m_tokens.put();
        if (u.group)
            finish_group(u, status);
        else
            finish(u.runs[0], status, wall);
        return true;
    }

    // Stops the runs under way (a leader's forked runs end with it,
    // cli::fork_untied) and reaps them; a stopped group's runs that had
    // finished wrote their status and count.
    void stop() {
        std::vector<pid_t> pids;
        for (const auto& [pid, unit_index] : m_running) pids.push_back(pid);
        cli::stop_children(pids);
        for (const auto& [pid, unit_index] : m_running) {
            if (!m_units[unit_index].group) continue;
            for (size_t i : m_units[unit_index].runs) {
                if (!fs::exists(run_dir(i) + "/status")) continue;
                double wall = 0;
                const int member = member_status(run_dir(i), 0, &wall, &m_rows[i].snapshot_ms);
                finish(i, member, wall);
            }
        }
    }

    const campaign_options& m_o;
    const std::vector<campaign_run>& m_plan;
    std::vector<campaign_row>& m_rows;
    std::FILE* m_log;
    const std::vector<unit> m_units;
    job_tokens m_tokens;
    std::map<pid_t, size_t> m_running;  // pid -> unit
    std::vector<std::chrono::steady_clock::time_point> m_started;
    size_t m_next = 0, m_done = 0;
    int m_broken = -1;
};

}  // namespace

namespace {

// Whether an interrupted run's row is the plan's run of its index.
bool same_run(const json& row, const campaign_run& r) {
    return row.value("fault", std::string()) == (r.fault.empty() ? "clean" : r.fault) &&
           row.value("seed", uint64_t{0}) == r.seed && row.value("frames", -1) == r.frames &&
           row.value("retry_limit", -1) == static_cast<int>(r.retry_limit) &&
           row.value("settings", std::vector<std::string>{}) == r.settings;
}

// The rows of out_dir's campaign.json that ran, by index, if it is the same
// campaign (name, seeds, shard, match); false and *error if not.
bool rows_to_keep(const campaign_options& o, std::map<int, json>* kept, std::string* error) {
    const std::string path = o.out_dir + "/campaign.json";
    json previous;
    if (!cli::read_resumed(o.out_dir, "campaign.json", &previous, error)) return false;
    const std::string shard = std::to_string(o.shard) + "/" + std::to_string(o.shards);
    if (previous.value("campaign", std::string()) != o.name ||
        previous.value("seeds", -1) != o.seeds || previous.value("shard", std::string()) != shard ||
        previous.value("match", std::string()) != o.match ||
        previous.value("paper_card", false) != o.paper_card ||
        cli::firmware_of_document(previous) != cli::firmware_identity_of(o.firmware, error)) {
        *error = "--resume: " + path + " is not this campaign (campaign, seeds, shard, match, " +
                 "--paper-card or firmware differ)";
        return false;
    }
    std::map<int, campaign_run> planned;
    for (const campaign_run& r : selected_runs(o)) planned[r.index] = r;
    for (const json& row : previous.value("rows", json::array())) {
        if (!row.value("ran", false)) continue;
        const int index = row.value("index", -1);
        const auto mine = planned.find(index);
        if (mine == planned.end() || !same_run(row, mine->second)) {
            *error = "--resume: run " + std::to_string(index) + " of " + path +
                     " is not this campaign's (its fault, seed, frames, RETRY_LIMIT or settings "
                     "differ: another stereosim's plan)";
            return false;
        }
        (*kept)[index] = row;
    }
    return true;
}

}  // namespace

std::vector<campaign_row> run_campaign(const campaign_options& given, std::FILE* log,
                                       std::string* error, json* document, int* interrupted) {
    campaign_options o = given;
    if (o.binary.empty()) o.binary = this_program();
    if (o.out_dir.empty()) o.out_dir = "campaign-" + o.name;
    std::map<int, json> kept;  // rows of an interrupted run that ran
    if (o.resume && !rows_to_keep(o, &kept, error)) return {};
    std::vector<campaign_run> plan;
    for (const campaign_run& r : selected_runs(o))
        if (!kept.count(r.index)) plan.push_back(r);
    std::vector<campaign_row> rows(plan.size());
    std::error_code ec;
    fs::create_directories(o.out_dir + "/runs", ec);
    if (ec) {
        *error = "cannot create " + o.out_dir + "/runs: " + ec.message();
        return {};
    }
    const cli::interrupt_catcher interrupt;
    const auto t0 = std::chrono::steady_clock::now();
    plan_runner runner(o, plan, rows, log);
    runner.run(interrupt);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const campaign_row& r : rows)
        if (r.finished) kept[r.run.index] = row_json(r);
    json all = json::array();
    for (auto& [index, row] : kept) all.push_back(std::move(row));
    json doc = campaign_document(o.name, std::to_string(o.shard) + "/" + std::to_string(o.shards),
                                 o.seeds, o.jobs, o.snapshots, wall, std::move(all));
    doc["match"] = o.match;
    doc["paper_card"] = o.paper_card;
    std::string unloadable;  // the command checked the plugin before the runs
    doc["firmware"] = cli::firmware_identity_of(o.firmware, &unloadable);
    const int signo = interrupt.caught();
    doc["complete"] = signo == 0 && runner.broken() < 0;
    if (runner.broken() >= 0) doc["stopped_at"] = runner.broken();
    if (signo != 0) doc["interrupted_by"] = cli::signal_name(signo);
    if (!write_campaign_files(o.out_dir, doc, error)) return {};
    if (document) *document = std::move(doc);
    if (interrupted) *interrupted = signo;
    return rows;
}

}  // namespace faults
