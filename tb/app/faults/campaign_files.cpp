#include "tb/app/faults/campaign_files.h"
#include "tb/app/cli/firmware_identity.h"

#include "tb/app/cli/staged_files.h"
#include "tb/app/faults/campaign_coverage.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace faults {

namespace {

using nlohmann::json;

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string fmt(double v, int decimals = 1) {
    if (v < 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

const char* const csv_columns[] = {"index",
                                   "fault",
                                   "kind",
                                   "seed",
                                   "frames",
                                   "retry_limit",
                                   "expected",
                                   "actual",
                                   "detected_by",
                                   "reported_by",
                                   "verdict_causes",
                                   "frames_to_detect",
                                   "frames_to_recover",
                                   "failed_starts",
                                   "pairs_discarded",
                                   "pairs_used_after_onset",
                                   "unsynced_pairs_used",
                                   "misses",
                                   "false_alarms",
                                   "sync_errors",
                                   "pairs_forwarded",
                                   "pairs_in_step",
                                   "pairs_processed",
                                   "pairs_dropped",
                                   "pairs_unaccounted",
                                   "unreported_sync_errors",
                                   "unreported_overflows",
                                   "identity_checked",
                                   "identity_mismatches",
                                   "hard_error_ms",
                                   "contract_ok",
                                   "wall_s",
                                   "violations"};

std::string csv_value(const json& j, const char* key) {
    if (!j.contains(key) || j[key].is_null()) return "";
    const json& v = j[key];
    if (v.is_string()) return csv_field(v.get<std::string>());
    if (v.is_array()) {
        std::string all;
        for (const json& s : v) all += (all.empty() ? "" : "; ") + s.get<std::string>();
        return csv_field(all);
    }
    if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
    if (v.is_number_float()) return fmt(v.get<double>(), 3);
    return v.dump();
}

void write_csv(std::ostream& csv, const json& all) {
    for (size_t c = 0; c < std::size(csv_columns); ++c) csv << (c ? "," : "") << csv_columns[c];
    csv << "\n";
    for (const json& r : all) {
        for (size_t c = 0; c < std::size(csv_columns); ++c)
            csv << (c ? "," : "") << csv_value(r, csv_columns[c]);
        csv << "\n";
    }
}

// "-" for a null (not detected, not recovered), else the number.
std::string count_or_dash(const json& v) {
    return v.is_number() ? v.dump() : std::string("-");
}

int int_of(const json& row, const char* key) {
    return row.value(key, json(0)).get<int>();
}

std::string table_row(const json& r) {
    char line[512];
    const std::string fault = r.at("fault");
    if (!r.at("ran").get<bool>()) {
        const bool crashed = r.value("actual", std::string()) == "crash";
        std::snprintf(line, sizeof line, "%-4d %-46s %5llu %3d  %s: %s\n", r.at("index").get<int>(),
                      fault.c_str(), static_cast<unsigned long long>(r.at("seed").get<uint64_t>()),
                      r.at("frames").get<int>(), crashed ? "CRASH" : "NOT RUN",
                      r.value("error", std::string()).c_str());
        return line;
    }
    const bool faulty = r.contains("detected_by");
    std::snprintf(
        line, sizeof line,
        "%-4d %-46s %5llu %3d  %-22s %-13s %-12s %4s %4s %4d %4d %4d %4d %4d %4d %4d %s\n",
        r.at("index").get<int>(), fault.c_str(),
        static_cast<unsigned long long>(r.at("seed").get<uint64_t>()), r.at("frames").get<int>(),
        r.at("expected").get<std::string>().c_str(), r.at("actual").get<std::string>().c_str(),
        faulty ? r.at("detected_by").get<std::string>().c_str() : "-",
        faulty ? count_or_dash(r.at("frames_to_detect")).c_str() : "-",
        faulty ? count_or_dash(r.at("frames_to_recover")).c_str() : "-",
        int_of(r, "pairs_discarded"), int_of(r, "pairs_forwarded"), int_of(r, "pairs_processed"),
        int_of(r, "pairs_dropped"), int_of(r, "unsynced_pairs_used"), int_of(r, "misses"),
        int_of(r, "false_alarms"), r.at("contract_ok").get<bool>() ? "ok" : "BROKEN");
    std::string out = line;
    for (const json& why : r.at("violations"))
        out += "       violation: " + why.get<std::string>() + "\n";
    if (r.value("not_judged", json()).is_string())
        out += "       not judged: " + r["not_judged"].get<std::string>() + "\n";
    return out;
}

}  // namespace

json campaign_document(const std::string& name, const std::string& shard, int seeds, int jobs,
                       bool snapshots, double wall_s, json rows) {
    int broken = 0, clean_frames = 0, false_alarms = 0, crashed = 0;
    for (const json& r : rows) {
        broken += !r.at("contract_ok").get<bool>();
        crashed += r.value("actual", std::string()) == "crash";
        if (r.at("ran").get<bool>() && r.at("fault") == "clean") {
            clean_frames += r.at("frames").get<int>();
            false_alarms += r.at("false_alarms").get<int>();
        }
    }
    json space = fault_space_coverage(rows);
    json safety = safety_class_shares(rows);
    return {{"campaign", name},
            {"shard", shard},
            {"seeds", seeds},
            {"jobs", jobs},
            {"snapshots", snapshots},
            {"runs", rows.size()},
            {"contract_broken", broken},
            {"crashed", crashed},
            {"clean_frames", clean_frames},
            {"clean_false_alarms", false_alarms},
            {"wall_s", wall_s},
            {"fault_space", std::move(space)},
            {"safety_classes", std::move(safety)},
            {"rows", std::move(rows)}};
}

std::string campaign_table(const json& campaign) {
    std::ostringstream out;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%-4s %-46s %5s %3s  %-22s %-13s %-12s %4s %4s %4s %4s %4s %4s %4s %4s %4s "
                  "%s\n",
                  "run", "fault", "seed", "fr", "expected", "actual", "detected_by", "det", "rec",
                  "disc", "fwd", "proc", "drop", "unsy", "miss", "fals", "contract");
    out << line;
    int unsynced = 0, forked = 0;
    for (const json& r : campaign.at("rows")) {
        out << table_row(r);
        if (!r.at("ran").get<bool>()) continue;
        unsynced += r.at("unsynced_pairs_used").get<int>();
        forked += r.at("snapshot_ms").is_number();
    }
    std::snprintf(line, sizeof line,
                  "\ncampaign %s shard %s: %zu runs, %d break the contract (%d crashed); clean "
                  "frames %d with %d false alarms; unsynced pairs used (all runs) %d; wall %.1f s "
                  "with %d jobs, %d runs forked from snapshots\n",
                  campaign.at("campaign").get<std::string>().c_str(),
                  campaign.at("shard").get<std::string>().c_str(), campaign.at("rows").size(),
                  campaign.at("contract_broken").get<int>(), campaign.value("crashed", 0),
                  campaign.at("clean_frames").get<int>(),
                  campaign.at("clean_false_alarms").get<int>(), unsynced,
                  campaign.at("wall_s").get<double>(), campaign.at("jobs").get<int>(), forked);
    out << line;
    out << "columns: det = frames from onset to detection, rec = frames from detection to the "
           "first in-step pair forwarded, disc = pairs discarded (SYNC_ERROR + OVERFLOW) from the "
           "onset, fwd / proc / drop = pairs forwarded by the card / processed / dropped by the "
           "firmware's overrun policy, unsy = unsynced pairs used, miss = out-of-step pairs "
           "forwarded, fals = false "
           "alarms\n";
    if (!campaign.value("complete", true)) {
        std::snprintf(line, sizeof line,
                      "INCOMPLETE: interrupted by %s; the %zu runs above finished, the others "
                      "did not run (`stereosim faults ... --resume DIR` runs only them)\n",
                      campaign.value("interrupted_by", std::string("a signal")).c_str(),
                      campaign.at("rows").size());
        out << line;
    }
    out << coverage_text(campaign);
    return out.str();
}

// Staged and renamed into place: a second signal or a full disk never leaves
// a half-written campaign.json for --resume to read.
bool write_campaign_files(const std::string& dir, const json& campaign, std::string* error) {
    cli::staged_files staged;
    if (!staged.open(dir, error)) return false;
    std::ofstream j(staged.staged_path("campaign.json")), csv(staged.staged_path("campaign.csv")),
        txt(staged.staged_path("campaign.txt"));
    j << campaign.dump(2) << "\n";
    write_csv(csv, campaign.at("rows"));
    txt << campaign_table(campaign);
    j.close();
    csv.close();
    txt.close();
    if (!j || !csv || !txt) {
        *error = "cannot write the campaign files into " + dir;
        return false;
    }
    return staged.commit(error);
}

bool merge_campaign_shards(const std::vector<json>& shards, json* merged, std::string* error) {
    std::map<int, json> rows;
    std::set<int> shard_numbers;
    int count = 0;
    double wall = 0;
    const json& first = shards.at(0);
    for (const json& s : shards) {
        int k = 0, m = 0;
        if (std::sscanf(s.at("shard").get<std::string>().c_str(), "%d/%d", &k, &m) != 2 ||
            s.at("campaign") != first.at("campaign") || s.at("seeds") != first.at("seeds") ||
            cli::firmware_of_document(s) != cli::firmware_of_document(first) ||
            (count && m != count)) {
            *error =
                "merge: the folders are not shards of one campaign (campaign, seeds, firmware, "
                "shard count differ)";
            return false;
        }
        count = m;
        if (!shard_numbers.insert(k).second) {
            *error = "merge: shard " + std::to_string(k) + "/" + std::to_string(m) + " given twice";
            return false;
        }
        wall = std::max(wall, s.at("wall_s").get<double>());
        for (const json& r : s.at("rows")) rows[r.at("index").get<int>()] = r;
    }
    std::string missing;
    for (int k = 1; k <= count; ++k)
        if (!shard_numbers.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (!missing.empty()) {
        *error = "merge: shards missing (of " + std::to_string(count) + "): " + missing;
        return false;
    }
    json all = json::array();
    for (auto& [index, row] : rows) all.push_back(std::move(row));
    *merged = campaign_document(first.at("campaign"), "1/1", first.at("seeds"), first.at("jobs"),
                                first.at("snapshots"), wall, std::move(all));
    bool complete = true;
    for (const json& s : shards) complete = complete && s.value("complete", true);
    (*merged)["match"] = first.value("match", std::string());
    (*merged)["paper_card"] = first.value("paper_card", false);
    (*merged)["firmware"] = cli::firmware_of_document(first);
    (*merged)["complete"] = complete;
    return true;
}

}  // namespace faults
