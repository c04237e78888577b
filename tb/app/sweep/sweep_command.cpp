#include "tb/app/sweep/sweep_command.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "tb/app/cli/firmware_identity.h"
#include "tb/app/cli/interrupt.h"
#include "tb/app/sweep/sweep_files.h"
#include "tb/app/sweep/sweep_plan.h"
#include "tb/app/sweep/sweep_runner.h"

namespace sweep {

namespace {

using json = nlohmann::json;

int bad_input(const std::string& message) {
    std::fprintf(stderr, "stereosim: error: %s\n", message.c_str());
    return 2;
}

// The sweep's own command line for a Slurm task (absolute paths; the task
// adds --jobs, --shard and --out).
std::vector<std::string> task_command(const sweep_options& o) {
    std::vector<std::string> c = {this_program(), "sweep"};
    for (const std::string& g : o.grid) c.insert(c.end(), {"--grid", g});
    if (!o.config_file.empty()) c.insert(c.end(), {"--config", cli::absolute_path(o.config_file)});
    if (!o.frames.empty()) c.insert(c.end(), {"--frames", o.frames});
    for (const std::string& s : o.sets) c.insert(c.end(), {"--set", s});
    if (o.screen) {
        c.insert(c.end(), {"--screen", "--screen-sample", std::to_string(o.screen_sample)});
        char margin[32];
        std::snprintf(margin, sizeof margin, "%.10g", o.screen_margin_ms);
        c.insert(c.end(), {"--screen-margin-ms", margin});
    }
    if (o.force) c.push_back("--force");
    if (o.keep_runs) c.push_back("--keep-runs");
    return c;
}

void print_summary(const json& summary, const std::string& dir) {
    std::printf("sweep: %zu points, %d co-simulated: %d within, %d over, %d not judged, %d failed",
                summary["points"].get<size_t>(), summary["simulated"].get<int>(),
                summary["within"].get<int>(), summary["over"].get<int>(),
                summary.value("not_judged", 0), summary["failed"].get<int>());
    const json& cf = summary["closed_form_only"];
    if (cf["within"].get<int>() + cf["over"].get<int>() > 0)
        std::printf("; closed form only: %d within, %d over", cf["within"].get<int>(),
                    cf["over"].get<int>());
    std::printf("\nclosed form agrees with the co-simulation on %d points, disagrees on %zu%s",
                summary["closed_form_agrees"].get<int>(), summary["closed_form_disagrees"].size(),
                summary["closed_form_disagrees"].empty() ? "" : " (points");
    for (const json& i : summary["closed_form_disagrees"]) std::printf(" %zu", i.get<size_t>());
    if (!summary["closed_form_disagrees"].empty()) std::printf(")");
    if (summary.value("not_judged", 0) > 0)
        std::printf(
            "\nnot judged: a run too short for every stage to run counts as no fit "
            "(sweep.json's not_judged says which stage and how many frames to ask for)");
    std::printf("\nwritten: %s/sweep.json, sweep.csv, frontier.csv, fitmap.png\n", dir.c_str());
}

// --resume: the points DIR's sweep.json ran, in place of the plan's, if it is
// the same sweep (grid, base settings, shard, screening).
bool keep_finished_points(const sweep_options& o, const json& previous, sweep_plan* plan,
                          std::string* error) {
    const std::string path = o.out_dir + "/sweep.json";
    const json header = sweep_header(o, *plan);
    for (const char* key :
         {"grid", "base", "shard", "screen", "screen_sample", "screen_margin_ms", "points_total"})
        if (previous.value(key, json()) != header.at(key)) {
            *error = "--resume: " + path + " is another sweep (its " + key + " differs)";
            return false;
        }
    std::map<json, json*> mine;
    for (json& p : plan->points) mine[p.at("index")] = &p;
    for (const json& p : previous.value("points", json::array())) {
        if (!p.value("ran", false)) continue;
        const auto it = mine.find(p.value("index", json()));
        if (it != mine.end()) *it->second = p;
    }
    return true;
}

}  // namespace

sweep_command::sweep_command(CLI::App& app) {
    sweep_options& o = m_options;
    m_app = app.add_subcommand("sweep",
                               "a grid of config keys, every point co-simulated "
                               "(docs/sweep.md)");
    m_app->add_option("--grid", o.grid, "KEY=V1,V2,... or KEY=LO:HI:STEP (repeat for more keys)")
        ->required();
    m_app->add_option("--config", o.config_file, "config file under every point (docs/config.md)");
    m_app->add_option("--set", o.sets, "KEY=VALUE under every point (repeatable)");
    m_app
        ->add_option("--firmware", o.firmware,
                     "the firmware under test at every point, a plugin .so (run.firmware, "
                     "docs/firmware-abi.md)")
        ->type_name("PATH");
    m_app->add_option("--frames", o.frames, "sync periods per point (run.frames)");
    m_app->add_option("--jobs", o.jobs, "points in parallel (default 2)");
    m_app->add_option("--shard", o.shard, "K/M: the K-th of M deterministic slices");
    m_app->add_option("--out", o.out_dir, "folder for sweep.json / .csv, frontier.csv, fitmap.png");
    m_app->add_flag("--screen", o.screen,
                    "closed form over the whole grid; co-simulate only near its boundary and a "
                    "sample of the rest");
    m_app->add_option("--screen-sample", o.screen_sample,
                      "with --screen: co-simulate every Nth point away from the boundary (10)");
    m_app->add_option("--screen-margin-ms", o.screen_margin_ms,
                      "with --screen: closed-form slack within this of 0 is near (0.25 ms)");
    m_app->add_flag("--force", o.force, "run a grid of more than 10,000 points");
    m_app->add_flag("--keep-runs", o.keep_runs, "keep every point's run folder under OUT/points");
    m_app->add_option("--resume", o.resume,
                      "DIR of an interrupted sweep: keep the points it ran, run the others (the "
                      "same grid and settings)");
    cli::add_slurm_options(m_app, &o.slurm);
}

int sweep_command::execute() {
    sweep_options& o = m_options;
    // The plugin is one more base setting (every point's run, the Slurm
    // tasks, --resume and merge compare it), by its absolute path.
    std::string plugin;
    if (!o.firmware.empty()) {
        plugin = cli::absolute_path(o.firmware);
        o.sets.push_back("run.firmware=" + plugin);
        o.firmware.clear();
    }
    if (!o.resume.empty()) {
        if (!o.out_dir.empty() && o.out_dir != o.resume)
            return bad_input("--resume DIR writes into DIR: no other --out");
        o.out_dir = o.resume;
    }
    sweep_plan plan;
    std::string error;
    if (!check_sweep(o, &plan, &error)) return bad_input(error);
    if (o.slurm.emit) {
        if (!o.resume.empty()) return bad_input("--resume runs here: no --emit-slurm");
        if (o.shard != "1/1")
            return bad_input("--emit-slurm: the array makes the shards; no --shard");
        const std::string sbatch =
            cli::write_slurm_array(o.slurm, "stereosim-sweep", task_command(o), o.out_dir, &error);
        if (sbatch.empty()) return bad_input(error);
        std::printf(
            "written: %s/job.sbatch (%d tasks over %zu points)\nsubmit: %s\nthen:   %s merge "
            "%s/shard-* --out %s\n",
            cli::absolute_path(o.out_dir).c_str(), o.slurm.tasks, plan.total, sbatch.c_str(),
            this_program().c_str(), cli::absolute_path(o.out_dir).c_str(),
            cli::absolute_path(o.out_dir).c_str());
        return 0;
    }
    json resumed;  // read before the closed form's minutes: a wrong DIR fails at once
    if (!o.resume.empty() && !cli::read_resumed(o.out_dir, "sweep.json", &resumed, &error))
        return bad_input(error);
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) return bad_input("cannot create " + o.out_dir + ": " + ec.message());
    const auto t0 = std::chrono::steady_clock::now();
    plan_points(o, &plan, stderr);
    std::fprintf(stderr, "sweep: closed form of %zu points (%zu firmware runs on the host)\n",
                 plan.points.size(), plan.host_runs);
    run_request request;
    request.binary = this_program();
    request.config_file = o.config_file;
    request.base_sets = o.sets;
    if (!o.frames.empty())
        request.base_sets.insert(request.base_sets.begin(), "run.frames=" + o.frames);
    request.out_dir = o.out_dir;
    request.jobs = o.jobs;
    request.keep_runs = o.keep_runs;
    if (!o.resume.empty() && !keep_finished_points(o, resumed, &plan, &error))
        return bad_input(error);
    int interrupted = 0;
    // Held until the files are written: a second signal does not cut them short.
    const cli::interrupt_catcher held;
    const int failed = run_points(request, plan.points, stderr, &interrupted);
    json sweep = sweep_header(o, plan);
    sweep["firmware"] = cli::firmware_identity_of(plugin, &error);
    sweep["complete"] = interrupted == 0;
    if (interrupted) sweep["interrupted_by"] = cli::signal_name(interrupted);
    sweep["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    sweep["summary"] = sweep_summary(plan.points);
    sweep["points"] = plan.points;
    std::string warning;
    if (!write_sweep_files(o.out_dir, sweep, &error, &warning)) return bad_input(error);
    if (!warning.empty()) std::fprintf(stderr, "stereosim: warning: %s\n", warning.c_str());
    print_summary(sweep["summary"], o.out_dir);
    if (!o.keep_runs) std::filesystem::remove(o.out_dir + "/points", ec);
    if (interrupted) {
        std::fprintf(stderr,
                     "stereosim: sweep: interrupted by %s: written to %s/sweep.json (incomplete: "
                     "the points under way have no figures); --resume %s runs them\n",
                     cli::signal_name(interrupted).c_str(), o.out_dir.c_str(), o.out_dir.c_str());
        cli::die_of(interrupted);
    }
    return failed > 0 ? 3 : 0;
}

}  // namespace sweep
