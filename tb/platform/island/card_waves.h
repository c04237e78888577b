// The waveform file a traced build of the card writes its whole RTL
// hierarchy into (stereosim run --waves, docs/waveforms.md). The run's pin
// trace sink offers it (pin_trace::card_file); an island whose sink has one
// builds the card verilated with --trace-fst or --trace (rtl/CMakeLists.txt)
// and registers it with the writer of the file's format before the file
// opens. Exactly one of the two writers is non-null.
#pragma once

class VerilatedFstC;
class VerilatedVcdC;

namespace platform {

class card_waves {
  public:
    virtual ~card_waves() = default;
    virtual VerilatedFstC* fst_writer() = 0;
    virtual VerilatedVcdC* vcd_writer() = 0;
};

// The trace depth an island asks of the card: every level of its hierarchy.
inline constexpr int card_trace_levels = 99;

}  // namespace platform
