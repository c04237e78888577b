// `stereosim faults` (docs/faults.md, docs/fault-contract.md):
//   stereosim faults --list
//   stereosim faults --campaign smoke|full [--seeds N] [--jobs J] [--shard K/M] [--out DIR]
//                    [--keep-runs] [--match TEXT] [--no-snapshots]
//                    [--emit-slurm [--slurm-tasks M ...]]  (docs/cluster.md)
// Exit codes: 0 every run kept the contract, 1 a run broke it (or did not
// run), 2 bad input.
#pragma once

#include <string>

#include "tb/app/cli/slurm_job.h"
#include "tb/app/faults/campaign.h"
#include "tb/app/faults/snapshots.h"

namespace CLI {
class App;
}

namespace faults {

class faults_command {
  public:
    // `make_extensions`: the run command's extensions, for the runs a
    // campaign forks from snapshots (empty: every run is spawned).
    faults_command(CLI::App& app, extensions_factory make_extensions);
    CLI::App* subcommand() const { return m_app; }
    int execute();

  private:
    CLI::App* m_app = nullptr;
    bool m_list = false;
    bool m_keep_runs = false;
    bool m_no_snapshots = false;
    extensions_factory m_make_extensions;
    std::string m_campaign;
    int m_seeds = 0;
    int m_jobs = 2;
    std::string m_shard = "1/1";
    std::string m_out;
    std::string m_resume;  // --resume DIR
    std::string m_binary;
    std::string m_firmware;
    bool m_paper_card = false;
    bool m_stop_on_violation = false;
    std::string m_match;
    cli::slurm_options m_slurm;

    // The Slurm job array of this campaign's shards (--emit-slurm).
    int emit_slurm(const campaign_options& o);
};

}  // namespace faults
