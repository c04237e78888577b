#include "tb/app/faults/faults_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "tb/app/cli/firmware_identity.h"
#include "tb/app/cli/interrupt.h"
#include "tb/app/faults/campaign.h"
#include "tb/app/faults/campaign_files.h"
#include "tb/app/faults/fault_spec.h"

namespace faults {

namespace {

int bad_input(const std::string& message) {
    std::fprintf(stderr, "stereosim: error: %s\n", message.c_str());
    return 2;
}

}  // namespace

faults_command::faults_command(CLI::App& app, extensions_factory make_extensions)
    : m_make_extensions(std::move(make_extensions)) {
    m_app = app.add_subcommand("faults", "fault kinds and the fault campaign (docs/faults.md)");
    m_app->add_flag("--list", m_list, "every fault kind with its parameters, defaults, ranges");
    m_app->add_option("--campaign", m_campaign, "run a campaign: smoke | full");
    m_app->add_option("--seeds", m_seeds, "seeds per fault spec (smoke 1, full 3)");
    m_app->add_option("--jobs", m_jobs, "runs in parallel (default 2)");
    m_app->add_option("--shard", m_shard, "K/M: run the K-th of M deterministic slices");
    m_app->add_option("--out", m_out, "folder for campaign.json/.csv/.txt (default campaign-NAME)");
    m_app->add_option("--resume", m_resume,
                      "DIR of an interrupted campaign: keep its finished runs, run the others "
                      "(the same --campaign, --seeds, --shard and --match)");
    m_app->add_flag("--keep-runs", m_keep_runs, "keep each run's report.json under OUT/runs");
    m_app->add_option("--binary", m_binary, "the stereosim to run (default: this program)");
    m_app
        ->add_option("--firmware", m_firmware,
                     "the firmware under test in every run, a plugin .so (docs/firmware-abi.md)")
        ->type_name("PATH");
    m_app->add_flag(
        "--paper-card", m_paper_card,
        "every run judges the paper's card: its frame-identity check off, "
        "extra-frame's stale pair the named hole of rule 1 (stereosim run --paper-card)");
    m_app->add_flag("--stop-on-violation", m_stop_on_violation,
                    "end the campaign at the first run that breaks the contract");
    m_app->add_flag("--no-snapshots", m_no_snapshots,
                    "run every run from the start (default: runs whose faults start later "
                    "share their fault-free prefix, forked at a snapshot)");
    m_app->add_option(
        "--match", m_match,
        "only the runs whose spec contains TEXT (A|B: either; 'clean': the clean runs)");
    cli::add_slurm_options(m_app, &m_slurm);
}

int faults_command::emit_slurm(const campaign_options& o) {
    if (o.shards != 1) return bad_input("--emit-slurm: the array makes the shards; no --shard");
    std::string error;
    if (o.out_dir.empty())
        return bad_input("--emit-slurm: give --out DIR (on a shared filesystem)");
    std::error_code ec;
    std::vector<std::string> command = {
        std::filesystem::read_symlink("/proc/self/exe", ec).string(), "faults", "--campaign",
        o.name};
    if (o.seeds) command.insert(command.end(), {"--seeds", std::to_string(o.seeds)});
    if (!o.binary.empty())
        command.insert(command.end(), {"--binary", cli::absolute_path(o.binary)});
    if (!o.firmware.empty()) command.insert(command.end(), {"--firmware", o.firmware});
    if (!o.match.empty()) command.insert(command.end(), {"--match", o.match});
    if (o.keep_runs) command.push_back("--keep-runs");
    if (!o.snapshots) command.push_back("--no-snapshots");
    if (o.stop_on_violation) command.push_back("--stop-on-violation");
    if (o.paper_card) command.push_back("--paper-card");
    const std::string sbatch =
        cli::write_slurm_array(m_slurm, "stereosim-faults", command, o.out_dir, &error);
    if (sbatch.empty()) return bad_input(error);
    const std::string dir = cli::absolute_path(o.out_dir);
    std::printf(
        "written: %s/job.sbatch (%d tasks)\nsubmit: %s\nthen:   %s merge %s/shard-* --out %s\n",
        dir.c_str(), m_slurm.tasks, sbatch.c_str(), command[0].c_str(), dir.c_str(), dir.c_str());
    return 0;
}

int faults_command::execute() {
    if (m_list) {
        std::fputs(kinds_listing().c_str(), stdout);
        if (m_campaign.empty()) return 0;
    }
    if (m_campaign.empty()) return bad_input("faults: give --list or --campaign smoke|full");
    campaign_options o;
    o.name = m_campaign;
    if (campaign_plan(o.name, 1).empty())
        return bad_input("--campaign: unknown campaign '" + m_campaign + "' (smoke or full)");
    if (m_seeds < 0 || m_seeds > 1000) return bad_input("--seeds: out of range 0..1000");
    if (m_jobs < 1 || m_jobs > 256) return bad_input("--jobs: out of range 1..256");
    int k = 0, m = 0;
    char extra = 0;
    if (std::sscanf(m_shard.c_str(), "%d/%d%c", &k, &m, &extra) != 2 || m < 1 || k < 1 || k > m)
        return bad_input("--shard: expected K/M with 1 <= K <= M, got '" + m_shard + "'");
    o.seeds = m_seeds;
    o.jobs = m_jobs;
    o.shard = k;
    o.shards = m;
    o.out_dir = m_out;
    if (!m_resume.empty()) {
        if (!m_out.empty() && m_out != m_resume)
            return bad_input("--resume DIR writes into DIR: no other --out");
        o.out_dir = m_resume;
        o.resume = true;
    }
    o.keep_runs = m_keep_runs;
    o.binary = m_binary;
    o.match = m_match;
    if (!m_firmware.empty()) {
        std::string why;
        if (cli::firmware_identity_of(m_firmware, &why).is_null()) return bad_input(why);
        o.firmware = cli::absolute_path(m_firmware);
    }
    o.snapshots = !m_no_snapshots;
    o.stop_on_violation = m_stop_on_violation;
    o.paper_card = m_paper_card;
    if (m_make_extensions) {
        o.run_group = [this](const std::vector<snapshot_member>& members, const std::string& binary,
                             const std::string& leader_log, const job_tokens& tokens) {
            return run_snapshot_group(members, binary, m_make_extensions, leader_log, tokens);
        };
    }
    std::string error;
    if (!cli::check_slurm_options(m_slurm, &error)) return bad_input(error);
    if (m_slurm.emit && o.resume) return bad_input("--resume runs here: no --emit-slurm");
    if (m_slurm.emit) return emit_slurm(o);
    nlohmann::json document;
    int interrupted = 0;
    run_campaign(o, stderr, &error, &document, &interrupted);
    if (!error.empty()) return bad_input(error);
    if (o.out_dir.empty()) o.out_dir = "campaign-" + o.name;
    std::fputs(campaign_table(document).c_str(), stdout);
    std::printf("written: %s/campaign.json, campaign.csv, campaign.txt\n", o.out_dir.c_str());
    if (interrupted) {
        std::fprintf(stderr,
                     "stereosim: faults: interrupted by %s: %zu runs finished, written to "
                     "%s/campaign.json (incomplete); --resume %s runs the others\n",
                     cli::signal_name(interrupted).c_str(), document.at("rows").size(),
                     o.out_dir.c_str(), o.out_dir.c_str());
        cli::die_of(interrupted);
    }
    if (document.contains("stopped_at"))
        std::fprintf(stderr,
                     "stereosim: faults: stopped at the first broken contract (run %d); "
                     "%zu runs finished, written to %s/campaign.json (incomplete)\n",
                     document.at("stopped_at").get<int>(), document.at("rows").size(),
                     o.out_dir.c_str());
    for (const nlohmann::json& r : document.at("rows"))
        if (!r.value("contract_ok", false)) return 1;
    return 0;
}

}  // namespace faults
