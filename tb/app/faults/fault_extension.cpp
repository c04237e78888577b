#include "tb/app/faults/fault_extension.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <utility>

#include "dsp/card_regs.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/faults/fault_report.h"
#include "tb/app/faults/fault_spec.h"
#include "tb/platform/platform_config.h"

namespace faults {

namespace {

// VERDICT's cause bits by their names in docs/card-registers.md.
std::string cause_names(uint32_t causes) {
    using namespace dsp::card_regs;
    const std::pair<uint32_t, const char*> names[] = {{verdict_l_window_mask, "L_WINDOW"},
                                                      {verdict_r_window_mask, "R_WINDOW"},
                                                      {verdict_l_dark_mask, "L_DARK"},
                                                      {verdict_r_dark_mask, "R_DARK"},
                                                      {verdict_l_vsync_mask, "L_VSYNC"},
                                                      {verdict_r_vsync_mask, "R_VSYNC"},
                                                      {verdict_start_timeout_mask, "START_TIMEOUT"},
                                                      {verdict_overflow_mask, "OVERFLOW"},
                                                      {verdict_l_frame_id_mask, "L_FRAME_ID"},
                                                      {verdict_r_frame_id_mask, "R_FRAME_ID"}};
    std::string out;
    for (const auto& [mask, name] : names)
        if (causes & mask) out += (out.empty() ? "" : "|") + std::string(name);
    return out;
}

class fault_extension final : public cli::run_extension {
  public:
    void add_options(CLI::App& run) override {
        run.add_option("--fault", m_texts,
                       "inject a fault KIND:KEY=VALUE,...[@frame=N|@ms=T] (repeatable; "
                       "stereosim faults --list, docs/faults.md)");
        run.add_option("--card-retry-limit", m_retry_limit,
                       "the card's RETRY_LIMIT: OE restarts before HARD_ERROR (default " +
                           std::to_string(m_retry_limit) + ")");
        m_rearms_option =
            run.add_option("--hard-error-rearms", m_rearms,
                           "the firmware's re-arms after a card hard error before it gives up "
                           "(firmware.hard_error_rearms; default: the firmware's own)");
        run.add_flag("--paper-card", m_paper_card,
                     "judge the paper's card: the firmware turns the card's frame-identity check "
                     "off (firmware.card_frame_id_check=0) and extra-frame's stale pair is the "
                     "named hole of rule 1 (docs/fault-contract.md)");
    }

    bool configure(const cli::run_setup& setup, platform::platform_config& config,
                   std::string* error) override {
        for (const std::string& text : m_texts) {
            const std::optional<fault_spec> spec = parse_fault_spec(text, error);
            if (!spec) return false;
            apply(*spec, config);
            m_specs.push_back(*spec);
        }
        if (m_retry_limit < 0 || m_retry_limit > 255) {
            *error = "--card-retry-limit: " + std::to_string(m_retry_limit) +
                     " out of range 0..255 (RETRY_LIMIT is 8 bits)";
            return false;
        }
        config.card_retry_limit = static_cast<uint32_t>(m_retry_limit);
        // The firmware's keys these options set, checked against its descriptor like --set.
        cli::run_setup with = setup;
        if (m_rearms_option->count() > 0)
            with.firmware_settings.emplace_back("firmware.hard_error_rearms", m_rearms);
        if (m_paper_card)
            with.firmware_settings.emplace_back("firmware.card_frame_id_check", false);
        if (with.firmware_settings.size() != setup.firmware_settings.size() &&
            !cli::resolve_firmware_settings(with, &config.firmware_settings, error)) {
            *error = (m_paper_card ? "--paper-card: " : "--hard-error-rearms: ") + *error;
            return false;
        }
        if (!m_paper_card && !m_specs.empty() &&
            platform::firmware_key(config, "card_frame_id_check", 1.0) == 0.0) {
            // Rule 1 has no exception with the check on; off, only the paper's card is judged.
            *error =
                "firmware.card_frame_id_check=0 turns the card's frame-identity check off, but "
                "--fault asks the contract for rule 1 without exception: add --paper-card to "
                "judge the paper's card";
            return false;
        }
        return true;
    }

    void attach(platform::platform_top& top) override { m_top = &top; }

    void add_to_report(nlohmann::json& report, const cli::run_result& run) override {
        if (!m_top) return;
        m_result = evaluate(*m_top, run.score, m_specs, m_paper_card);
        faults::add_to_report(report, m_result);
    }

    std::vector<std::string> summary_lines(const cli::run_result& /*run*/) override {
        std::vector<std::string> lines;
        for (size_t i = 0; i < m_result.specs.size(); ++i) {
            const fault_observation& f = m_result.run.faults[i];
            const verdict& v = m_result.verdicts[i];
            char line[512];
            const std::string detected = !f.detected ? std::string("no")
                                         : f.causes != 0
                                             ? f.detected_by + " (" + cause_names(f.causes) + ")"
                                             : f.detected_by;
            std::snprintf(line, sizeof line,
                          "fault %s: %s (contract %s) onset %.3f ms, detected %s, %s",
                          f.spec.c_str(), outcome_name(v.actual), v.expected_text.c_str(),
                          f.onset_ms, detected.c_str(), v.ok ? "contract kept" : "CONTRACT BROKEN");
            lines.push_back(line);
            for (const std::string& why : v.violations) lines.push_back("  violation: " + why);
        }
        if (m_result.specs.empty() && !m_result.verdicts.empty() && !m_result.verdicts[0].ok)
            for (const std::string& why : m_result.verdicts[0].violations)
                lines.push_back("violation: " + why);
        return lines;
    }

    std::string broken_verdict(const cli::run_result& /*run*/) override {
        if (m_specs.empty() || m_result.contract_ok()) return "";
        int lines = 0;
        std::string first;
        for (const verdict& v : m_result.verdicts)
            for (const std::string& why : v.violations) {
                if (first.empty()) first = why;
                ++lines;
            }
        return "fault contract broken (" + std::to_string(lines) + " violation(s), " +
               "report.json fault_run.violations): " + first;
    }

  private:
    std::vector<std::string> m_texts;
    // The card's reset value.
    int m_retry_limit = static_cast<int>(dsp::card_regs::retry_limit_reset);
    int m_rearms = 0;
    CLI::Option* m_rearms_option = nullptr;
    bool m_paper_card = false;
    std::vector<fault_spec> m_specs;
    platform::platform_top* m_top = nullptr;
    fault_run_result m_result;
};

}  // namespace

std::unique_ptr<cli::run_extension> make_fault_extension() {
    return std::make_unique<fault_extension>();
}

}  // namespace faults
