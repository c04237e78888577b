#include "tb/app/sweep/merge_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "tb/app/cli/firmware_identity.h"
#include "tb/app/faults/campaign_files.h"
#include "tb/app/sweep/sweep_files.h"
#include "tb/app/sweep/sweep_plan.h"

namespace sweep {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "stereosim: error: %s\n", message.c_str());
    return code;
}

bool read_json(const std::string& path, json* out, std::string* error) {
    std::ifstream in(path);
    if (!in) return false;
    try {
        *out = json::parse(in);
        return true;
    } catch (const std::exception& e) {
        *error = path + ": not JSON (" + e.what() + ")";
        return false;
    }
}

// "K/M" of a document; false if malformed.
bool shard_of(const json& doc, int* k, int* m) {
    const json& s = doc.value("shard", json());
    return s.is_string() && std::sscanf(s.get<std::string>().c_str(), "%d/%d", k, m) == 2 &&
           *k >= 1 && *k <= *m;
}

std::string index_list(const std::vector<size_t>& indices) {
    std::string s;
    for (size_t i = 0; i < indices.size() && i < 12; ++i)
        s += (i ? ", " : "") + std::to_string(indices[i]);
    if (indices.size() > 12) s += ", ... (" + std::to_string(indices.size()) + " in all)";
    return s;
}

// The sweep shards as one document; *code 2 or 3 and *error if not.
bool merge_sweeps(const std::vector<json>& shards, json* merged, int* code, std::string* error) {
    const json& first = shards.front();
    int count = 0;
    std::set<int> present;
    std::map<size_t, json> points;
    double wall = 0;
    for (const json& s : shards) {
        int k = 0, m = 0;
        if (!shard_of(s, &k, &m) || s.at("grid") != first.at("grid") ||
            s.at("base") != first.at("base") || s.at("screen") != first.at("screen") ||
            cli::firmware_of_document(s) != cli::firmware_of_document(first) ||
            (count && m != count)) {
            *error =
                "merge: the folders are not shards of one sweep (grid, base settings, screen, "
                "firmware or shard count differ)";
            return false;
        }
        count = m;
        if (!present.insert(k).second) {
            *error = "merge: shard " + std::to_string(k) + "/" + std::to_string(m) + " given twice";
            return false;
        }
        wall = std::max(wall, s.value("wall_s", 0.0));
        for (const json& p : s.at("points")) points[p.at("index").get<size_t>()] = p;
    }
    const size_t total = first.at("points_total").get<size_t>();
    std::vector<size_t> missing;
    for (size_t i = 0; i < total; ++i)
        if (!points.count(i)) missing.push_back(i);
    if (!missing.empty()) {
        std::string shards_missing;
        for (int k = 1; k <= count; ++k)
            if (!present.count(k))
                shards_missing += (shards_missing.empty() ? "" : ", ") + std::to_string(k);
        *code = 3;
        *error = "merge: shard(s) " + shards_missing + " of " + std::to_string(count) +
                 " missing: points " + index_list(missing) + " not merged";
        return false;
    }
    *merged = first;
    (*merged)["shard"] = "1/1";
    (*merged)["wall_s"] = wall;
    std::vector<json> all;
    for (auto& [index, p] : points) all.push_back(std::move(p));
    (*merged)["summary"] = sweep_summary(all);
    (*merged)["points"] = all;
    return true;
}

}  // namespace

merge_command::merge_command(CLI::App& app) {
    m_app = app.add_subcommand("merge",
                               "merge the shard folders of a sweep or a fault campaign "
                               "(docs/cluster.md)");
    m_app->add_option("dirs", m_dirs, "the shard folders (DIR/shard-*)")->required();
    m_app->add_option("--out", m_out, "folder for the merged files")->required();
}

int merge_command::execute() {
    std::vector<json> sweeps, campaigns;
    std::vector<std::string> without;
    std::string error;
    for (const std::string& dir : m_dirs) {
        json doc;
        if (read_json(dir + "/sweep.json", &doc, &error))
            sweeps.push_back(std::move(doc));
        else if (read_json(dir + "/campaign.json", &doc, &error))
            campaigns.push_back(std::move(doc));
        else if (!error.empty())
            return fail(2, error);
        else
            without.push_back(dir);
    }
    if (!sweeps.empty() && !campaigns.empty())
        return fail(2, "merge: a mix of sweep and campaign folders");
    if (sweeps.empty() && campaigns.empty())
        return fail(2, "merge: no sweep.json or campaign.json in " + m_dirs.front() +
                           (m_dirs.size() > 1 ? " or the other folders" : ""));
    if (!without.empty())
        std::fprintf(stderr,
                     "stereosim: warning: no sweep.json or campaign.json in %s (a failed task?)\n",
                     without.front().c_str());
    json merged;
    int code = 2;
    const bool ok = sweeps.empty() ? faults::merge_campaign_shards(campaigns, &merged, &error)
                                   : merge_sweeps(sweeps, &merged, &code, &error);
    if (!ok) return fail(error.find("missing") != std::string::npos ? 3 : code, error);
    std::error_code ec;
    fs::create_directories(m_out, ec);
    if (ec) return fail(2, "cannot create " + m_out + ": " + ec.message());
    std::string warning;
    const bool written = sweeps.empty() ? faults::write_campaign_files(m_out, merged, &error)
                                        : write_sweep_files(m_out, merged, &error, &warning);
    if (!written) return fail(3, error);
    if (!warning.empty()) std::fprintf(stderr, "stereosim: warning: %s\n", warning.c_str());
    std::printf("merged %zu shards into %s/%s\n", m_dirs.size() - without.size(), m_out.c_str(),
                sweeps.empty() ? "campaign.json, campaign.csv, campaign.txt"
                               : "sweep.json, sweep.csv, frontier.csv, fitmap.png");
    return 0;
}

}  // namespace sweep
