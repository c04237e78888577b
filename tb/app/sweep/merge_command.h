// `stereosim merge DIR... --out OUT` (docs/cluster.md): the shard folders of
// one sweep (sweep.json) or one fault campaign (campaign.json) as the files
// the unsharded run writes (wall times aside). A shard missing or without
// its file is named, with the points or runs it held; nothing is written.
//
// Exit codes: 0 merged, 2 bad input (not shards of one sweep or campaign),
// 3 shards missing.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sweep {

class merge_command {
  public:
    explicit merge_command(CLI::App& app);
    CLI::App* subcommand() const { return m_app; }
    int execute();

  private:
    CLI::App* m_app = nullptr;
    std::vector<std::string> m_dirs;
    std::string m_out;
};

}  // namespace sweep
