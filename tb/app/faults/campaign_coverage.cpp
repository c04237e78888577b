#include "tb/app/faults/campaign_coverage.h"

#include <cstdio>
#include <map>
#include <vector>

#include "tb/app/faults/fault_spec.h"

namespace faults {

namespace {

using nlohmann::json;

const char* const phases[] = {"vertical_blanking", "dark_rows",   "active_rows",
                              "oe_restart",        "first_check", "bus_burst"};
const char* const phase_heads[] = {"blank", "dark", "active", "restart", "first", "burst"};
// The modes the plan must reach for every kind: capture mode / DSK version.
const char* const modes[] = {"overlapped/v1", "sequential/v1", "overlapped/v3", "sequential/v3"};
const char* const classes[] = {"detected", "safe", "latent", "residual", "none"};

std::string mode_of(const json& row) {
    return row.value("mode", std::string("overlapped")) + "/v" +
           std::to_string(row.value("dsk", 1));
}

}  // namespace

json fault_space_coverage(const json& rows) {
    // kind -> sensor -> counts
    std::map<std::string, std::map<std::string, json>> cells;
    for (const kind_info& k : fault_kinds()) {
        const std::vector<std::string> sensors = is_sensor_fault(k.type)
                                                     ? std::vector<std::string>{"L", "R"}
                                                     : std::vector<std::string>{"-"};
        for (const std::string& s : sensors) {
            json c = {{"kind", k.name}, {"sensor", s}, {"runs", 0}};
            for (const char* p : phases) c["phases"][p] = 0;
            for (const char* m : modes) c["modes"][m] = 0;
            cells[k.name][s] = c;
        }
    }
    for (const json& row : rows) {
        if (!row.value("ran", false) || !row.contains("faults")) continue;
        const std::string mode = mode_of(row);
        for (const json& f : row.at("faults")) {
            if (f.value("outcome", std::string()) == "not_in_effect") continue;
            auto kind = cells.find(f.value("kind", std::string()));
            if (kind == cells.end()) continue;
            auto cell = kind->second.find(f.value("sensor", std::string("-")));
            if (cell == kind->second.end()) continue;
            json& c = cell->second;
            c["runs"] = c["runs"].get<int>() + 1;
            for (const json& p : f.value("onset_phases", json::array()))
                if (c["phases"].contains(p.get<std::string>()))
                    c["phases"][p.get<std::string>()] =
                        c["phases"][p.get<std::string>()].get<int>() + 1;
            c["modes"][mode] = c["modes"].value(mode, 0) + 1;
        }
    }
    json out = json::array();
    for (auto& [kind, sensors] : cells)
        for (auto& [sensor, c] : sensors) {
            json holes = json::array();
            for (const char* p : phases)
                if (c["phases"][p].get<int>() == 0) holes.push_back(p);
            for (const char* m : modes)
                if (c["modes"][m].get<int>() == 0) holes.push_back(m);
            c["holes"] = holes;
            out.push_back(c);
        }
    return out;
}

json safety_class_shares(const json& rows) {
    json counts = json::object();
    for (const char* c : classes) counts[c] = 0;
    int total = 0;
    for (const json& row : rows) {
        if (!row.value("ran", false) || !row.contains("faults")) continue;
        for (const json& f : row.at("faults")) {
            const std::string c = f.value("safety_class", std::string("none"));
            if (!counts.contains(c)) continue;
            counts[c] = counts[c].get<int>() + 1;
            ++total;
        }
    }
    counts["faults"] = total;
    return counts;
}

std::string coverage_text(const json& campaign) {
    std::string out;
    char line[512];
    const json& space = campaign.at("fault_space");
    out +=
        "\nfault space: runs whose fault took effect, by onset phase and mode (o/s = "
        "overlapped / sequential capture, v1/v3 = DSK)\n";
    std::snprintf(line, sizeof line, "%-12s %-3s %4s", "kind", "sns", "runs");
    out += line;
    for (const char* h : phase_heads) {
        std::snprintf(line, sizeof line, " %7s", h);
        out += line;
    }
    out += "  o/v1 s/v1 o/v3 s/v3  holes\n";
    int holes = 0;
    for (const json& c : space) {
        std::snprintf(line, sizeof line, "%-12s %-3s %4d", c.at("kind").get<std::string>().c_str(),
                      c.at("sensor").get<std::string>().c_str(), c.at("runs").get<int>());
        out += line;
        for (const char* p : phases) {
            std::snprintf(line, sizeof line, " %7d", c.at("phases").at(p).get<int>());
            out += line;
        }
        out += " ";
        for (const char* m : modes) {
            std::snprintf(line, sizeof line, " %4d", c.at("modes").at(m).get<int>());
            out += line;
        }
        out += " ";
        for (const json& h : c.at("holes")) out += " " + h.get<std::string>();
        holes += static_cast<int>(c.at("holes").size());
        out += "\n";
    }
    const json& shares = campaign.at("safety_classes");
    const int total = shares.at("faults").get<int>();
    std::snprintf(line, sizeof line,
                  "fault space holes: %d\nsafety classes (ISO 26262) of %d faults:", holes, total);
    out += line;
    for (const char* c : classes) {
        const int n = shares.at(c).get<int>();
        std::snprintf(line, sizeof line, " %s %d (%.0f %%)", c, n, total ? 100.0 * n / total : 0.0);
        out += line;
    }
    return out + "\n";
}

}  // namespace faults
