// The waveform file a traced build of the card writes its whole RTL
// hierarchy into (stereosim run --waves, docs/waveforms.md). The run's pin
// trace sink offers it (pin_trace::card_file); an island whose sink has one
// builds the card verilated with --trace-fst or --trace (rtl/CMakeLists.txt)
// and registers it with the writer of the file's format before the file
// opens. Exactly one of the two writers is non-null.
#pragma once

#include <type_traits>
#include <utility>

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

// Whether a verilated card model traces into `writer` (built with
// --trace-fst: VerilatedFstC, --trace: VerilatedVcdC; an untraced build has
// neither).
template <class card_model, class writer, class = void>
inline constexpr bool traces_into = false;
template <class card_model, class writer>
inline constexpr bool traces_into<
    card_model, writer,
    std::void_t<decltype(std::declval<card_model&>().trace(std::declval<writer*>(), 0))>> = true;
template <class card_model>
inline constexpr bool is_traced_card =
    traces_into<card_model, VerilatedFstC> || traces_into<card_model, VerilatedVcdC>;

// Registers a traced card with the file's writer; nothing for an untraced one.
template <class card_model>
void trace_card_into(card_model& card, card_waves& waves) {
    if constexpr (traces_into<card_model, VerilatedFstC>) {
        card.trace(waves.fst_writer(), card_trace_levels);
    } else if constexpr (traces_into<card_model, VerilatedVcdC>) {
        card.trace(waves.vcd_writer(), card_trace_levels);
    }
}

}  // namespace platform
