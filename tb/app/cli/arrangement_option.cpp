#include "tb/app/cli/arrangement_option.h"

#include <CLI/CLI.hpp>

namespace cli {

namespace {

class arrangement_option : public run_extension {
  public:
    void add_options(CLI::App& run) override {
        run.add_option("--arrangement", m_name,
                       "fast (cores in one SystemC thread, default) | pins (sc_signals, "
                       "verilator --sc; the reference, ~4x slower)")
            ->check(CLI::IsMember({"fast", "pins"}));
    }
    bool configure(const run_setup& /*setup*/, platform::platform_config& config,
                   std::string* error) override {
        config.arrangement =
            m_name == "pins" ? platform::arrangement_kind::pins : platform::arrangement_kind::fast;
        // Both arrangements feed the pin trace (--vcd): the same signals, the same VCD.
        (void)error;
        return true;
    }

  private:
    std::string m_name = "fast";
};

}  // namespace

std::unique_ptr<run_extension> make_arrangement_option() {
    return std::make_unique<arrangement_option>();
}

}  // namespace cli
