// `stereosim replay init DIR --left PATTERN --right PATTERN --focal-px F
// --baseline-mm B [...]` (docs/replay.md): writes DIR/replay.txt, the
// manifest of a replay of the user's own image pairs, and checks it the way
// a run will (scene::replay: every file there, PNG or JPEG, one size). A
// PATTERN is a file with %d / %0Nd for the frame number, or one file (one
// pair, held for as many frames as the run asks).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace cli {

struct replay_init_options {
    std::string dir;
    std::string left, right;  // file patterns (or single files)
    double focal_px = 0.0;
    double baseline_mm = 0.0;
    std::string principal_left, principal_right;  // "X,Y"; empty: the image centre
    std::string truth;                            // a truth CSV (docs/replay.md), optional
    std::string after_last;                       // error | hold | loop; empty: the default
};

class replay_command {
  public:
    explicit replay_command(CLI::App& app);
    CLI::App* subcommand() const { return m_app; }
    int execute();

  private:
    CLI::App* m_app = nullptr;
    CLI::App* m_init = nullptr;
    replay_init_options m_options;
};

// Writes and checks the manifest; false and *error (one line) if the input
// is bad, nothing left behind; *summary = what was written.
bool write_replay_manifest(const replay_init_options& o, std::string* summary, std::string* error);

}  // namespace cli
