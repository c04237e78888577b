#include "tb/app/sweep/sweep_grid.h"

#include <cmath>
#include <cstdio>
#include <set>

#include "tb/app/cli/firmware_keys.h"

namespace sweep {

namespace {

using json = nlohmann::json;

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    size_t begin = 0;
    for (;;) {
        const size_t end = text.find(sep, begin);
        parts.push_back(text.substr(begin, end - begin));
        if (end == std::string::npos) return parts;
        begin = end + 1;
    }
}

bool parse_number(const std::string& text, double* value) {
    char* end = nullptr;
    *value = std::strtod(text.c_str(), &end);
    return !text.empty() && end && *end == '\0' && std::isfinite(*value);
}

// LO:HI:STEP on a numeric key, every value range-checked.
bool parse_range(const cli::config_key& key, const std::string& text, grid_axis* axis,
                 std::string* error) {
    if (key.type != cli::key_type::integer && key.type != cli::key_type::real) {
        *error = "--grid " + key.name + ": a range needs a number key, this one is " +
                 cli::key_type_name(key.type);
        return false;
    }
    const std::vector<std::string> parts = split(text, ':');
    double lo = 0, hi = 0, step = 0;
    if (parts.size() != 3 || !parse_number(parts[0], &lo) || !parse_number(parts[1], &hi) ||
        !parse_number(parts[2], &step)) {
        *error = "--grid " + key.name + "=" + text + ": a range is LO:HI:STEP (three numbers)";
        return false;
    }
    if (step <= 0 || lo > hi) {
        *error = "--grid " + key.name + "=" + text + ": needs LO <= HI and STEP > 0";
        return false;
    }
    const double count = std::floor((hi - lo) / step + 1e-9) + 1;
    if (count > 100000) {
        *error = "--grid " + key.name + "=" + text + ": more than 100,000 values";
        return false;
    }
    for (int i = 0; i < static_cast<int>(count); ++i) {
        const double v = lo + i * step;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.10g", v);
        json checked;
        if (!cli::parse_value(key, buf, &checked, error)) {
            *error = "--grid " + key.name + "=" + text + ": " + *error;
            return false;
        }
        axis->values.push_back(checked);
    }
    return true;
}

// A firmware's own key (firmware.NAME beyond the platform's table): its
// values as a config file would hold them, each checked against the
// firmware's descriptor with its point's setup (sweep_plan).
bool parse_firmware_axis(const std::string& list, grid_axis* axis, std::string* error) {
    std::vector<json> values;
    if (list.find(':') != std::string::npos) {
        const std::vector<std::string> parts = split(list, ':');
        double lo = 0, hi = 0, step = 0;
        if (parts.size() != 3 || !parse_number(parts[0], &lo) || !parse_number(parts[1], &hi) ||
            !parse_number(parts[2], &step) || step <= 0 || lo > hi || (hi - lo) / step > 100000) {
            *error = "--grid " + axis->key + "=" + list +
                     ": a range is LO:HI:STEP, LO <= HI, STEP > 0, at most 100,000 values";
            return false;
        }
        const double count = std::floor((hi - lo) / step + 1e-9) + 1;
        for (int i = 0; i < static_cast<int>(count); ++i) {
            const double v = lo + i * step;
            values.push_back(v == std::floor(v) ? json(static_cast<int64_t>(v)) : json(v));
        }
    } else {
        for (const std::string& item : split(list, ',')) {
            if (item.empty()) {
                *error = "--grid " + axis->key + "=" + list + ": an empty value";
                return false;
            }
            values.push_back(cli::typed_setting(json(item)));
        }
    }
    std::set<std::string> seen;
    for (const json& v : values) {
        if (!seen.insert(v.dump()).second) {
            *error = "--grid " + axis->key + "=" + list + ": value " + v.dump() + " given twice";
            return false;
        }
        axis->values.push_back(v);
    }
    return true;
}

}  // namespace

bool parse_axis(const std::string& text, grid_axis* axis, std::string* error) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0) {
        *error = "--grid '" + text + "': expected KEY=V1,V2,... or KEY=LO:HI:STEP";
        return false;
    }
    axis->key = text.substr(0, eq);
    axis->values.clear();
    const cli::config_key* key = cli::find_key(axis->key);
    const std::string list = text.substr(eq + 1);
    if (!key && cli::is_firmware_own_key(axis->key) && !list.empty())
        return parse_firmware_axis(list, axis, error);
    if (!key) {
        *error = "--grid: " + cli::unknown_key_message(axis->key);
        return false;
    }
    if (list.empty()) {
        *error = "--grid " + axis->key + ": no values";
        return false;
    }
    if (list.find(':') != std::string::npos && key->type != cli::key_type::text)
        return parse_range(*key, list, axis, error);
    std::set<std::string> seen;
    for (const std::string& item : split(list, ',')) {
        if (item.empty()) {
            *error = "--grid " + axis->key + "=" + list + ": an empty value";
            return false;
        }
        json checked;
        if (!cli::parse_value(*key, item, &checked, error)) {
            *error = "--grid " + axis->key + "=" + list + ": " + *error;
            return false;
        }
        if (!seen.insert(checked.dump()).second) {
            *error = "--grid " + axis->key + "=" + list + ": value " + item + " given twice";
            return false;
        }
        axis->values.push_back(checked);
    }
    return true;
}

bool parse_grid(const std::vector<std::string>& args, std::vector<grid_axis>* axes,
                std::string* error) {
    axes->clear();
    if (args.empty()) {
        *error = "sweep: give at least one --grid KEY=V1,V2,...";
        return false;
    }
    std::set<std::string> keys;
    for (const std::string& arg : args) {
        grid_axis axis;
        if (!parse_axis(arg, &axis, error)) return false;
        if (!keys.insert(axis.key).second) {
            *error = "--grid " + axis.key + ": the key is given twice";
            return false;
        }
        axes->push_back(std::move(axis));
    }
    return true;
}

size_t point_count(const std::vector<grid_axis>& axes, size_t cap) {
    size_t n = 1;
    for (const grid_axis& a : axes) {
        n *= a.values.size();
        if (n > cap) return cap + 1;
    }
    return n;
}

grid_point point_at(const std::vector<grid_axis>& axes, size_t index) {
    grid_point p;
    p.index = index;
    p.settings.resize(axes.size());
    size_t rest = index;
    for (size_t a = axes.size(); a-- > 0;) {
        const size_t n = axes[a].values.size();
        p.settings[a] = {axes[a].key, axes[a].values[rest % n]};
        rest /= n;
    }
    return p;
}

std::vector<grid_point> shard_points(const std::vector<grid_axis>& axes, int shard, int shards) {
    std::vector<grid_point> points;
    const size_t total = point_count(axes, static_cast<size_t>(-2));
    for (size_t i = static_cast<size_t>(shard - 1); i < total; i += static_cast<size_t>(shards))
        points.push_back(point_at(axes, i));
    return points;
}

bool parse_shard(const std::string& text, int* shard, int* shards, std::string* error) {
    int k = 0, m = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &k, &m, &extra) != 2 || m < 1 || k < 1 || k > m ||
        m > 100000) {
        *error = "--shard: expected K/M with 1 <= K <= M, got '" + text + "'";
        return false;
    }
    *shard = k;
    *shards = m;
    return true;
}

std::string value_text(const nlohmann::json& value) {
    return value.is_string() ? value.get<std::string>() : value.dump();
}

}  // namespace sweep
