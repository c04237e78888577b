#include "tb/app/faults/fault_report.h"

namespace faults {

using nlohmann::json;

namespace {

json null_if(bool have, double v) {
    return have ? json(v) : json(nullptr);
}

double num(const json& j, const char* key, double fallback = -1) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

int integer(const json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<int>() : 0;
}

std::vector<uint32_t> pair_list(const json& j, const char* key) {
    std::vector<uint32_t> out;
    if (j.contains(key) && j[key].is_array())
        for (const json& n : j[key])
            if (n.is_number_unsigned()) out.push_back(n.get<uint32_t>());
    return out;
}

json params_json(const contract_params& p) {
    return {{"retry_limit", p.retry_limit},
            {"hard_error_rearms", p.hard_error_rearms},
            {"dark_threshold", p.dark_threshold},
            {"black_level", p.black_level},
            {"dark_sigma", p.dark_sigma},
            {"line_pclks", p.line_pclks},
            {"frame_lines", p.frame_lines},
            {"checked_span_pclks", p.checked_span_pclks},
            {"words_per_pair", p.words_per_pair},
            {"eclk_per_word", p.eclk_per_word},
            {"eclk_ns", p.eclk_ns},
            {"period_ms", p.period_ms},
            {"paper_card", p.paper_card},
            {"hard_error_bound_periods", hard_error_bound_periods(p)}};
}

contract_params params_of(const json& j) {
    contract_params p;
    p.retry_limit = static_cast<uint32_t>(num(j, "retry_limit", p.retry_limit));
    p.hard_error_rearms = static_cast<uint32_t>(num(j, "hard_error_rearms", p.hard_error_rearms));
    p.dark_threshold = static_cast<uint32_t>(num(j, "dark_threshold", p.dark_threshold));
    p.black_level = static_cast<int>(num(j, "black_level", p.black_level));
    p.dark_sigma = num(j, "dark_sigma", p.dark_sigma);
    p.line_pclks = static_cast<int>(num(j, "line_pclks", p.line_pclks));
    p.frame_lines = static_cast<int>(num(j, "frame_lines", p.frame_lines));
    p.checked_span_pclks = static_cast<int>(num(j, "checked_span_pclks", p.checked_span_pclks));
    p.words_per_pair = num(j, "words_per_pair", p.words_per_pair);
    p.eclk_per_word = num(j, "eclk_per_word", p.eclk_per_word);
    p.eclk_ns = num(j, "eclk_ns", p.eclk_ns);
    p.period_ms = num(j, "period_ms", p.period_ms);
    p.paper_card = j.value("paper_card", false);
    return p;
}

json recovery_json(const recovery_observation& r) {
    return {{"failed_checks", r.failed_checks},
            {"card_restarts", r.card_restarts},
            {"card_hard_errors", r.card_hard_errors},
            {"longest_streak", r.longest_streak},
            {"firmware_rearms", r.firmware_rearms},
            {"watchdog_firings", r.watchdog_firings},
            {"give_up_cause", r.give_up_cause},
            {"hard_errors_early", r.hard_errors_early},
            {"hard_errors_missed", r.hard_errors_missed},
            {"actions_without_check", r.actions_without_check},
            {"checks_without_action", r.checks_without_action},
            {"unexplained_rearms", r.unexplained_rearms},
            {"early_watchdogs", r.early_watchdogs},
            {"missed_watchdogs", r.missed_watchdogs},
            {"unexplained_overflows", r.unexplained_overflows},
            {"unexplained_silences", r.unexplained_silences},
            {"unexplained", r.unexplained}};
}

recovery_observation recovery_of(const json& j) {
    recovery_observation r;
    if (!j.is_object()) return r;
    r.failed_checks = integer(j, "failed_checks");
    r.card_restarts = integer(j, "card_restarts");
    r.card_hard_errors = integer(j, "card_hard_errors");
    r.longest_streak = integer(j, "longest_streak");
    r.firmware_rearms = integer(j, "firmware_rearms");
    r.watchdog_firings = integer(j, "watchdog_firings");
    r.give_up_cause = j.value("give_up_cause", std::string("none"));
    r.hard_errors_early = integer(j, "hard_errors_early");
    r.hard_errors_missed = integer(j, "hard_errors_missed");
    r.actions_without_check = integer(j, "actions_without_check");
    r.checks_without_action = integer(j, "checks_without_action");
    r.unexplained_rearms = integer(j, "unexplained_rearms");
    r.early_watchdogs = integer(j, "early_watchdogs");
    r.missed_watchdogs = integer(j, "missed_watchdogs");
    r.unexplained_overflows = integer(j, "unexplained_overflows");
    r.unexplained_silences = integer(j, "unexplained_silences");
    if (j.contains("unexplained") && j["unexplained"].is_array())
        for (const json& line : j["unexplained"])
            if (line.is_string()) r.unexplained.push_back(line.get<std::string>());
    return r;
}

}  // namespace

bool fault_run_result::contract_ok() const {
    for (const verdict& v : verdicts)
        if (!v.ok) return false;
    return true;
}

namespace {

// One --fault's object in report["faults"].
json fault_json(const std::string& spec_text, const fault_observation& f, const verdict& v) {
    return {
        {"spec", spec_text},
        {"canonical", f.spec},
        {"kind", fault_type_name(f.type)},
        {"hook", kind_of(f.type).hook},
        {"in_effect", f.in_effect},
        {"onset_ms", null_if(f.in_effect, f.onset_ms)},
        {"onset_frame", f.in_effect ? json(f.onset_frame) : json(nullptr)},
        {"detected", f.detected},
        {"detected_by", f.detected_by},
        {"detect_ms", null_if(f.detected, f.detect_ms)},
        {"frames_to_detect", f.detected ? json(f.frames_to_detect) : json(nullptr)},
        {"masked_checks", f.masked_checks},
        {"verdict_causes", f.causes},
        {"detect_start_in_step", f.detect_start_in_step},
        {"also_explained_by", f.also_explained_by},
        {"reported", f.reported},
        {"reported_by", f.reported_by},
        {"report_ms", null_if(f.reported, f.report_ms)},
        {"onset_start_out_of_step", f.onset_start_out_of_step},
        {"onset_frame_cut", f.onset_frame_cut},
        {"frame_id_check", f.frame_id_check},
        {"onset_phases", f.onset_phases},
        {"resumed_ms", null_if(f.resumed_ms >= 0, f.resumed_ms)},
        {"pair_ms_min", null_if(f.pair_ms_min >= 0, f.pair_ms_min)},
        {"slowed_ms_max", null_if(f.slowed_ms_max >= 0, f.slowed_ms_max)},
        {"slowed_pairs", f.slowed_pairs},
        {"dropped_pairs", f.dropped_pairs},
        {"recovered", f.recovered},
        {"recover_ms", null_if(f.recovered, f.recover_ms)},
        {"frames_to_recover", f.recovered ? json(f.frames_to_recover) : json(nullptr)},
        {"failed_starts", f.failed_starts},
        {"oe_starts_after", f.oe_starts_after},
        {"pairs_discarded", f.pairs_discarded},
        {"pairs_used", f.pairs_used},
        {"unsynced_pairs_used", f.unsynced_pairs_used},
        {"stale_pairs_used", f.stale_pairs_used},
        {"pairs_dropped", f.pairs_dropped},
        {"outcome", outcome_name(v.actual)},
        {"expected", v.expected_text},
        {"contract_ok", v.ok},
        {"violations", v.violations},
    };
}

// report["fault_run"]: the run-wide figures and the contract's settings.
json fault_run_json(const fault_run_result& r) {
    const run_observation& run = r.run;
    json violations = json::array();
    for (const verdict& v : r.verdicts)
        for (const std::string& s : v.violations) violations.push_back(s);
    return {
        {"frames", run.frames},
        {"period_ms", run.period_ms},
        {"mode", run.mode},
        {"dsk_version", run.dsk_version},
        {"end_ms", run.end_ms},
        {"pairs_forwarded", run.pairs_forwarded},
        {"pairs_processed", run.pairs_processed},
        {"pairs_rejected", run.pairs_rejected},
        {"pairs_dropped", run.pairs_dropped},
        {"pairs_in_step", run.pairs_in_step},
        {"pairs_unaccounted", run.pairs_unaccounted},
        {"unaccounted_pairs", run.unaccounted_pairs},
        {"unreported_sync_errors", run.unreported_sync_errors},
        {"unreported_overflows", run.unreported_overflows},
        {"unreported_in_step", run.unreported_in_step},
        {"unrearmed_overflows", run.unrearmed_overflows},
        {"identity_checked", run.identity_checked},
        {"identity_mismatches", run.identity_mismatches},
        {"mismatched_pairs", run.mismatched_pairs},
        {"missing_reports", run.missing_reports},
        {"card_sync_errors", run.card_sync_errors},
        {"card_overflows", run.card_overflows},
        {"firmware_sync_errors", run.firmware_sync_errors},
        {"oe_starts", run.oe_starts},
        {"rearms", run.rearms},
        {"unsynced_pairs_used", run.unsynced_pairs_used},
        {"misses", run.misses},
        {"used_before_verdict", run.used_before_verdict},
        {"false_alarms", run.false_alarms},
        {"sync_errors_before_onset", run.sync_errors_before_onset},
        {"hard_error", run.hard_error},
        {"hard_error_ms", null_if(run.hard_error, run.hard_error_ms)},
        {"failed_checks_before_give_up", run.failed_checks_before_give_up},
        {"truth_available", run.truth_available},
        {"boxes_scored", run.boxes_scored},
        {"points_scored", run.points_scored},
        {"max_box_err_px", run.max_box_err_px},
        {"max_depth_err_pct", run.max_depth_err_pct},
        {"recovery", recovery_json(run.recovery)},
        {"contract_params", params_json(r.params)},
        {"contract_ok", r.contract_ok()},
        {"violations", violations},
    };
}

// The run-wide figures back from report["fault_run"].
run_observation run_of(const json& j) {
    run_observation run;
    run.frames = integer(j, "frames");
    run.mode = j.value("mode", std::string("overlapped"));
    run.dsk_version = j.contains("dsk_version") ? integer(j, "dsk_version") : 1;
    run.period_ms = num(j, "period_ms", 24.5);
    run.end_ms = num(j, "end_ms", 0);
    run.firmware_started = true;
    run.pairs_forwarded = integer(j, "pairs_forwarded");
    run.pairs_processed = integer(j, "pairs_processed");
    run.pairs_rejected = integer(j, "pairs_rejected");
    run.pairs_dropped = integer(j, "pairs_dropped");
    run.pairs_in_step = integer(j, "pairs_in_step");
    run.pairs_unaccounted = integer(j, "pairs_unaccounted");
    run.unaccounted_pairs = pair_list(j, "unaccounted_pairs");
    run.unreported_sync_errors = integer(j, "unreported_sync_errors");
    run.unreported_overflows = integer(j, "unreported_overflows");
    run.unreported_in_step = integer(j, "unreported_in_step");
    run.unrearmed_overflows = integer(j, "unrearmed_overflows");
    run.identity_checked = integer(j, "identity_checked");
    run.identity_mismatches = integer(j, "identity_mismatches");
    run.mismatched_pairs = pair_list(j, "mismatched_pairs");
    run.missing_reports = j.value("missing_reports", json::array()).get<std::vector<std::string>>();
    run.card_sync_errors = integer(j, "card_sync_errors");
    run.card_overflows = integer(j, "card_overflows");
    run.firmware_sync_errors = integer(j, "firmware_sync_errors");
    run.oe_starts = integer(j, "oe_starts");
    run.rearms = integer(j, "rearms");
    run.unsynced_pairs_used = integer(j, "unsynced_pairs_used");
    run.misses = integer(j, "misses");
    run.used_before_verdict = integer(j, "used_before_verdict");
    run.false_alarms = integer(j, "false_alarms");
    run.sync_errors_before_onset = integer(j, "sync_errors_before_onset");
    run.hard_error = j.value("hard_error", false);
    run.hard_error_ms = num(j, "hard_error_ms");
    run.failed_checks_before_give_up = integer(j, "failed_checks_before_give_up");
    run.truth_available = j.value("truth_available", true);
    run.boxes_scored = integer(j, "boxes_scored");
    run.points_scored = integer(j, "points_scored");
    run.max_box_err_px = num(j, "max_box_err_px", 0);
    run.max_depth_err_pct = num(j, "max_depth_err_pct", 0);
    run.recovery = recovery_of(j.value("recovery", json::object()));
    return run;
}

// One --fault's observation back from its object in report["faults"].
fault_observation observation_of(const json& f, const fault_spec& spec) {
    fault_observation o;
    o.spec = f.value("canonical", canonical(spec));
    o.type = spec.type;
    o.in_effect = f.value("in_effect", false);
    o.onset_ms = num(f, "onset_ms");
    o.onset_frame = static_cast<int64_t>(num(f, "onset_frame"));
    o.detected = f.value("detected", false);
    o.detected_by = f.value("detected_by", std::string("none"));
    o.detect_ms = num(f, "detect_ms");
    o.frames_to_detect = static_cast<int>(num(f, "frames_to_detect"));
    o.causes = static_cast<uint32_t>(integer(f, "verdict_causes"));
    o.detect_start_in_step = f.value("detect_start_in_step", true);
    o.also_explained_by = f.value("also_explained_by", 0u);
    o.masked_checks = integer(f, "masked_checks");
    o.reported = f.value("reported", false);
    o.reported_by = f.value("reported_by", std::string("none"));
    o.report_ms = num(f, "report_ms");
    o.onset_start_out_of_step = f.value("onset_start_out_of_step", false);
    o.onset_frame_cut = f.value("onset_frame_cut", false);
    o.frame_id_check = f.value("frame_id_check", true);
    if (f.contains("onset_phases") && f["onset_phases"].is_array())
        for (const json& p : f["onset_phases"])
            if (p.is_string()) o.onset_phases.push_back(p.get<std::string>());
    o.resumed_ms = num(f, "resumed_ms");
    o.pair_ms_min = num(f, "pair_ms_min");
    o.slowed_ms_max = num(f, "slowed_ms_max");
    o.slowed_pairs = integer(f, "slowed_pairs");
    o.dropped_pairs = pair_list(f, "dropped_pairs");
    o.recovered = f.value("recovered", false);
    o.recover_ms = num(f, "recover_ms");
    o.frames_to_recover = static_cast<int>(num(f, "frames_to_recover"));
    o.failed_starts = integer(f, "failed_starts");
    o.oe_starts_after = integer(f, "oe_starts_after");
    o.pairs_discarded = integer(f, "pairs_discarded");
    o.pairs_used = integer(f, "pairs_used");
    o.unsynced_pairs_used = integer(f, "unsynced_pairs_used");
    o.stale_pairs_used = integer(f, "stale_pairs_used");
    o.pairs_dropped = integer(f, "pairs_dropped");
    return o;
}

}  // namespace

void add_to_report(json& report, const fault_run_result& r) {
    json list = json::array();
    for (size_t i = 0; i < r.specs.size(); ++i)
        list.push_back(fault_json(r.specs[i].text, r.run.faults[i], r.verdicts[i]));
    report["faults"] = list;
    report["fault_run"] = fault_run_json(r);
}

bool read_from_report(const json& report, fault_run_result* r, std::string* error) {
    if (!report.contains("fault_run") || !report["fault_run"].is_object() ||
        !report.contains("faults") || !report["faults"].is_array()) {
        *error = "report.json has no faults / fault_run";
        return false;
    }
    const json& j = report["fault_run"];
    *r = fault_run_result{};
    r->params = params_of(j.value("contract_params", json::object()));
    r->run = run_of(j);
    run_observation& run = r->run;
    for (const json& f : report["faults"]) {
        std::string parse_error;
        const std::optional<fault_spec> spec =
            parse_fault_spec(f.value("spec", std::string()), &parse_error);
        if (!spec) {
            *error = parse_error;
            return false;
        }
        r->specs.push_back(*spec);
        run.faults.push_back(observation_of(f, *spec));
    }
    note_expected_give_ups(r->specs, r->params, &run);
    if (r->specs.empty()) r->verdicts.push_back(check_clean(run));
    for (size_t i = 0; i < r->specs.size(); ++i)
        r->verdicts.push_back(check(run.faults[i], r->specs[i], r->params, run));
    return true;
}

}  // namespace faults
