#include "tb/app/sweep/sweep_plan.h"

#include <cmath>

#include "tb/app/cli/firmware_keys.h"
#include "tb/app/sweep/sweep_point.h"

namespace sweep {

namespace {

using json = nlohmann::json;

bool add_setting(const std::string& option, const std::string& set,
                 std::vector<cli::key_assignment>* base, std::string* error) {
    const size_t eq = set.find('=');
    if (eq == std::string::npos) {
        *error = option + " '" + set + "': expected key=value";
        return false;
    }
    const cli::config_key* key = cli::find_key(set.substr(0, eq));
    if (!key && cli::is_firmware_own_key(set.substr(0, eq))) {  // checked per point
        base->push_back({set.substr(0, eq), cli::typed_setting(json(set.substr(eq + 1)))});
        return true;
    }
    if (!key) {
        *error = option + ": " + cli::unknown_key_message(set.substr(0, eq));
        return false;
    }
    json value;
    if (!cli::parse_value(*key, set.substr(eq + 1), &value, error)) {
        *error = option + ": " + *error;
        return false;
    }
    base->push_back({key->name, value});
    return true;
}

// The config file, then --frames, then every --set in order (as `run`).
bool base_assignments(const sweep_options& o, std::vector<cli::key_assignment>* base,
                      std::string* error) {
    if (!o.config_file.empty() && !cli::read_config_file(o.config_file, base, error)) return false;
    if (!o.frames.empty() && !add_setting("--frames", "run.frames=" + o.frames, base, error))
        return false;
    for (const std::string& set : o.sets)
        if (!add_setting("--set", set, base, error)) return false;
    return true;
}

std::string point_text(const grid_point& p) {
    std::string s;
    for (const cli::key_assignment& a : p.settings)
        s += (s.empty() ? "" : " ") + a.key + "=" + value_text(a.value);
    return s;
}

bool setup_of(const sweep_plan& plan, const grid_point& p, cli::run_setup* setup,
              std::string* error) {
    std::vector<cli::key_assignment> all = plan.base;
    all.insert(all.end(), p.settings.begin(), p.settings.end());
    *setup = cli::run_setup{};
    if (cli::apply_assignments(all, setup, error) && cli::validate_setup(*setup, error))
        return true;
    *error = "point " + std::to_string(p.index) + " (" + point_text(p) + "): " + *error;
    return false;
}

// Grid neighbours of a point: one step along one axis.
std::vector<size_t> neighbours(const std::vector<grid_axis>& axes, size_t index) {
    std::vector<size_t> out;
    size_t stride = 1;
    for (size_t a = axes.size(); a-- > 0;) {
        const size_t n = axes[a].values.size();
        const size_t coord = index / stride % n;
        if (coord > 0) out.push_back(index - stride);
        if (coord + 1 < n) out.push_back(index + stride);
        stride *= n;
    }
    return out;
}

}  // namespace

bool check_sweep(const sweep_options& o, sweep_plan* plan, std::string* error) {
    if (o.out_dir.empty()) {
        *error = "sweep: --out DIR is required";
        return false;
    }
    if (o.jobs < 1 || o.jobs > 256) {
        *error = "--jobs: out of range 1..256";
        return false;
    }
    if (o.screen_sample < 1) {
        *error = "--screen-sample: must be >= 1";
        return false;
    }
    if (!parse_grid(o.grid, &plan->axes, error) ||
        !parse_shard(o.shard, &plan->shard, &plan->shards, error) ||
        !base_assignments(o, &plan->base, error) || !cli::check_slurm_options(o.slurm, error))
        return false;
    plan->total = point_count(plan->axes, max_points_without_force);
    if (plan->total > max_points_without_force && !o.force) {
        *error = "sweep: the grid has more than 10,000 points; give --force to run it";
        return false;
    }
    plan->total = point_count(plan->axes, static_cast<size_t>(-2));
    cli::run_setup setup;
    for (size_t i = 0; i < plan->total; ++i)
        if (!setup_of(*plan, point_at(plan->axes, i), &setup, error)) return false;
    return true;
}

void plan_points(const sweep_options& o, sweep_plan* plan, std::FILE* log) {
    closed_form_cache cache;
    const auto closed_form = [&](size_t index) {
        cli::run_setup setup;
        std::string error;
        setup_of(*plan, point_at(plan->axes, index), &setup, &error);  // checked before
        const size_t runs = cache.host_runs();
        json cf = cache.estimate(setup);
        if (log && cache.host_runs() > runs)
            std::fprintf(log, "sweep: closed form, host firmware run %zu done\n",
                         cache.host_runs());
        return cf;
    };
    std::vector<json> whole;  // --screen: the closed form of every point
    if (o.screen)
        for (size_t i = 0; i < plan->total; ++i) whole.push_back(closed_form(i));
    plan->points.clear();
    for (const grid_point& p : shard_points(plan->axes, plan->shard, plan->shards)) {
        json point = point_skeleton(p);
        point["closed_form"] = o.screen ? whole[p.index] : closed_form(p.index);
        bool simulate = true;
        if (o.screen) {
            const json& v = whole[p.index]["verdict"];
            const json& slack = whole[p.index]["slack_ms"];
            bool near = !v.is_string() || std::fabs(slack.get<double>()) < o.screen_margin_ms;
            for (size_t n : neighbours(plan->axes, p.index))
                near = near || whole[n]["verdict"] != v;
            simulate = near || p.index % static_cast<size_t>(o.screen_sample) == 0;
            point["screen"] = near ? "boundary" : simulate ? "sample" : "closed_form";
        }
        point["simulate"] = simulate;
        plan->points.push_back(std::move(point));
    }
    plan->host_runs = cache.host_runs();
}

json sweep_header(const sweep_options& o, const sweep_plan& plan) {
    json grid = json::array();
    for (const grid_axis& a : plan.axes) grid.push_back({{"key", a.key}, {"values", a.values}});
    json base = json::array();
    for (const cli::key_assignment& a : plan.base)
        base.push_back({{"key", a.key}, {"value", a.value}});
    return {{"tool", "stereosim sweep"},
            {"schema_version", 1},
            {"grid", grid},
            {"base", base},
            {"points_total", plan.total},
            {"shard", std::to_string(plan.shard) + "/" + std::to_string(plan.shards)},
            {"screen", o.screen},
            {"screen_sample", o.screen ? json(o.screen_sample) : json(nullptr)},
            {"screen_margin_ms", o.screen ? json(o.screen_margin_ms) : json(nullptr)},
            {"jobs", o.jobs}};
}

json sweep_summary(const std::vector<json>& points) {
    int simulated = 0, within = 0, over = 0, not_judged = 0, failed = 0, cf_within = 0, cf_over = 0,
        agree = 0;
    json disagree = json::array();
    for (const json& p : points) {
        const json& cf = p.value("closed_form", json::object());
        if (!p.value("simulate", false)) {
            cf_within += cf.value("verdict", json()) == "within";
            cf_over += cf.value("verdict", json()) == "over";
            continue;
        }
        ++simulated;
        if (!p.value("ran", false)) {
            ++failed;
            continue;
        }
        within += p["verdict"] == "within";
        over += p["verdict"] == "over";
        not_judged += p["verdict"] == "not_judged";
        const json& agrees = p.value("closed_form_agrees", json());
        if (agrees == true) ++agree;
        if (agrees == false) disagree.push_back(p["index"]);
    }
    return {{"points", points.size()},
            {"simulated", simulated},
            {"within", within},
            {"over", over},
            {"not_judged", not_judged},
            {"failed", failed},
            {"closed_form_only", {{"within", cf_within}, {"over", cf_over}}},
            {"closed_form_agrees", agree},
            {"closed_form_disagrees", disagree}};
}

}  // namespace sweep
