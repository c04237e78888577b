#include "tb/app/faults/fault_spec.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace faults {

namespace {

const param_info sensor_param{
    "sensor", "L|R", 0, 0, false, nullptr, "which sensor (L left, R right)"};

std::vector<kind_info> make_kinds() {
    std::vector<kind_info> k;
    k.push_back(
        {fault_type::skew,
         "skew",
         "sensor start_skew",
         "idle clocks (lines x line + pixels) inserted before one frame: it and every "
         "later edge come that late",
         {sensor_param,
          {"lines", nullptr, 0, 524, false, "0", "whole lines of skew"},
          {"pixels", nullptr, 0, 799, false, "0", "pixel clocks of skew (lines + pixels > 0)"}}});
    k.push_back(
        {fault_type::drop_line,
         "drop-line",
         "sensor dropped_line",
         "one readout line carries no HREF (no pixels); timing otherwise unchanged",
         {sensor_param,
          {"line", nullptr, 0, 524, false, "0",
           "line of the trigger frame (the first readout line at or after it; @frame only)"}}});
    k.push_back({fault_type::drop_frame,
                 "drop-frame",
                 "sensor dropped_frame",
                 "one frame has no VSYNC and no HREF pulse; its time slot is consumed",
                 {sensor_param}});
    k.push_back({fault_type::extra_frame,
                 "extra-frame",
                 "sensor extra_frame",
                 "an extra frame repeating the trigger frame's image is inserted after it",
                 {sensor_param}});
    k.push_back({fault_type::drift,
                 "drift",
                 "sensor pclk_drift",
                 "the sensor runs on its own oscillator, period error ppm (+ slower); continuing",
                 {sensor_param,
                  {"ppm", nullptr, -100000, 100000, false, nullptr, "period error, ppm (not 0)"}}});
    k.push_back({fault_type::glitch,
                 "glitch",
                 "sensor vsync_glitch / href_glitch",
                 "VSYNC or HREF inverted for `width` clocks from the trigger (where driven)",
                 {sensor_param,
                  {"signal", "vsync|href", 0, 0, false, nullptr, "the pin inverted"},
                  {"width", nullptr, 1, 420000, false, "1", "pixel clocks inverted"}}});
    k.push_back(
        {fault_type::dark_leak,
         "dark-leak",
         "sensor dark_leak",
         "every dark pixel reads `level` (plus noise) instead of black; continuing",
         {sensor_param, {"level", nullptr, 0, 255, false, "255", "what dark pixels read"}}});
    k.push_back({fault_type::stuck_bit,
                 "stuck-bit",
                 "sensor stuck_data_bit",
                 "DATA[bit] reads `value` on every driven word; continuing",
                 {sensor_param,
                  {"bit", nullptr, 0, 7, false, nullptr, "data bit"},
                  {"value", nullptr, 0, 1, false, "1", "the level it is stuck at"}}});
    k.push_back({fault_type::dead,
                 "dead",
                 "sensor never_start",
                 "every OE rise from the trigger on is ignored: the sensor never (re)starts",
                 {sensor_param}});
    k.push_back({fault_type::oe_stuck,
                 "oe-stuck",
                 "sensor ignore_oe",
                 "every OE fall from the trigger on is ignored: the sensor never restarts",
                 {sensor_param}});
    k.push_back({fault_type::emif_wait,
                 "emif-wait",
                 "emif::ardy_fault",
                 "the board glue between the card's ARDY and the DSP's holds the DSP's ARDY low "
                 "`cycles` extra ECLK on every access to the CE space",
                 {{"cycles", nullptr, 1, 1000, false, nullptr, "extra wait states per access"},
                  {"ce", nullptr, 2, 3, false, "3", "CE space: 2 registers, 3 pixel ports"}}});
    k.push_back({fault_type::cpu_slow,
                 "cpu-slow",
                 "c6416_sc::set_cycle_scale",
                 "every CPU cycle charged from the trigger on costs `factor` times as long",
                 {{"factor", nullptr, 1.001, 100, true, nullptr,
                   "slow-down factor (> 1, up to 3 decimals)"}}});
    return k;
}

bool parse_number(const std::string& text, bool decimal, double* value) {
    if (text.empty()) return false;
    char* end = nullptr;
    if (decimal) {
        *value = std::strtod(text.c_str(), &end);
        if (!std::isfinite(*value)) return false;
    } else {
        const long long v = std::strtoll(text.c_str(), &end, 10);
        *value = static_cast<double>(v);
    }
    return end && *end == '\0' && !std::isspace(static_cast<unsigned char>(text[0]));
}

std::string format_number(double v) {
    char buf[64];
    if (v == std::floor(v) && std::fabs(v) < 1e15)
        std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
    else
        std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string range_text(const param_info& p) {
    if (p.choices) return std::string("one of ") + p.choices;
    return (p.decimal ? std::string("a number in ") : std::string("an integer in ")) +
           format_number(p.min) + ".." + format_number(p.max);
}

// The index of `value` among p.choices ("L|R"), or -1.
int choice_index(const param_info& p, const std::string& value) {
    std::string all = p.choices;
    size_t start = 0;
    for (int i = 0;; ++i) {
        const size_t bar = all.find('|', start);
        const std::string c = all.substr(start, bar == std::string::npos ? bar : bar - start);
        if (c == value) return i;
        if (bar == std::string::npos) return -1;
        start = bar + 1;
    }
}

std::string kind_names() {
    std::string names;
    for (const kind_info& k : fault_kinds())
        names += (names.empty() ? "" : ", ") + std::string(k.name);
    return names;
}

}  // namespace

const std::vector<kind_info>& fault_kinds() {
    static const std::vector<kind_info> kinds = make_kinds();
    return kinds;
}

const kind_info& kind_of(fault_type type) {
    return fault_kinds()[static_cast<size_t>(type)];
}

const char* fault_type_name(fault_type type) {
    return kind_of(type).name;
}

bool is_sensor_fault(fault_type type) {
    return type != fault_type::emif_wait && type != fault_type::cpu_slow;
}

namespace {

// The parsers below return "" or why the spec is bad.
using param_values = std::map<std::string, double>;

const kind_info* find_kind(const std::string& name) {
    const kind_info* kind = nullptr;
    for (const kind_info& k : fault_kinds())
        if (name == k.name) kind = &k;
    return kind;
}

std::string unknown_param(const kind_info& kind, const std::string& key) {
    std::string names;
    for (const param_info& q : kind.params)
        names += (names.empty() ? "" : ", ") + std::string(q.name);
    return "unknown parameter '" + key + "' for " + kind.name +
           (names.empty() ? " (it takes none)" : " (parameters: " + names + ")");
}

// One "key=value" of the kind's parameters.
std::string parse_param(const kind_info& kind, const std::string& item, param_values* values) {
    const size_t eq = item.find('=');
    if (item.empty() || eq == std::string::npos || eq == 0)
        return "expected key=value, got '" + item + "'";
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const param_info* p = nullptr;
    for (const param_info& q : kind.params)
        if (key == q.name) p = &q;
    if (!p) return unknown_param(kind, key);
    if (values->count(key)) return "parameter '" + key + "' given twice";
    double v = 0;
    if (p->choices) {
        const int i = choice_index(*p, value);
        if (i < 0) return "bad value '" + value + "' for " + key + " (" + range_text(*p) + ")";
        v = i;
    } else if (!parse_number(value, p->decimal, &v) || v < p->min || v > p->max) {
        return "bad value '" + value + "' for " + key + " (" + range_text(*p) + ")";
    }
    (*values)[key] = v;
    return "";
}

// Parameters: key=value, comma separated; then the defaults of those not given.
std::string parse_params(const kind_info& kind, const std::string& params, bool given,
                         param_values* values) {
    size_t start = 0;
    while (given && start <= params.size()) {
        const size_t comma = params.find(',', start);
        const std::string item =
            params.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        start = comma == std::string::npos ? params.size() + 1 : comma + 1;
        const std::string why = parse_param(kind, item, values);
        if (!why.empty()) return why;
    }
    for (const param_info& p : kind.params) {
        if (values->count(p.name)) continue;
        if (!p.default_text) return std::string("missing parameter '") + p.name + "'";
        double v = 0;
        if (p.choices)
            v = choice_index(p, p.default_text);
        else
            parse_number(p.default_text, p.decimal, &v);
        (*values)[p.name] = v;
    }
    return "";
}

// Trigger: frame=N or ms=T.
std::string parse_trigger(const std::string& trigger, trigger_spec* when) {
    const size_t eq = trigger.find('=');
    const std::string key = trigger.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : trigger.substr(eq + 1);
    double v = 0;
    if (key == "frame" && parse_number(value, false, &v) && v >= 0 && v <= 1e9) {
        when->kind = trigger_spec::by::frame;
        when->frame = static_cast<uint64_t>(v);
    } else if (key == "ms" && parse_number(value, true, &v) && v >= 0 && v <= 1e7) {
        when->kind = trigger_spec::by::ms;
        when->ms = v;
    } else {
        return "bad trigger '@" + trigger +
               "' (expected @frame=N with N >= 0 or @ms=T with T >= 0)";
    }
    return "";
}

// The parsed values into the spec's fields of its kind, with the checks
// that involve more than one value.
std::string apply_params(const param_values& values, fault_spec* spec) {
    const auto get = [&](const char* name) {
        const auto it = values.find(name);
        return it != values.end() ? it->second : 0.0;
    };
    spec->camera = is_sensor_fault(spec->type) ? static_cast<int>(get("sensor")) : -1;
    switch (spec->type) {
        case fault_type::skew:
            spec->lines = static_cast<int>(get("lines"));
            spec->pixels = static_cast<int>(get("pixels"));
            if (spec->lines + spec->pixels == 0) return "skew needs lines or pixels > 0";
            break;
        case fault_type::drop_line:
            spec->line = static_cast<int>(get("line"));
            if (spec->line != 0 && spec->when.kind != trigger_spec::by::frame)
                return "parameter 'line' needs a @frame=N trigger";
            break;
        case fault_type::drift:
            spec->ppm = static_cast<int32_t>(get("ppm"));
            if (spec->ppm == 0) return "bad value '0' for ppm (not 0)";
            break;
        case fault_type::glitch:
            spec->href = get("signal") == 1;
            spec->width = static_cast<int>(get("width"));
            break;
        case fault_type::dark_leak:
            spec->level = static_cast<int>(get("level"));
            break;
        case fault_type::stuck_bit:
            spec->bit = static_cast<int>(get("bit"));
            spec->value = static_cast<int>(get("value"));
            break;
        case fault_type::emif_wait:
            spec->cycles = static_cast<uint32_t>(get("cycles"));
            spec->ce = static_cast<int>(get("ce"));
            break;
        case fault_type::cpu_slow:
            spec->factor = get("factor");
            if (std::fabs(spec->factor * 1000 - std::round(spec->factor * 1000)) > 1e-6)
                return "bad value for factor (at most 3 decimals)";
            break;
        default:
            break;
    }
    return "";
}

}  // namespace

std::optional<fault_spec> parse_fault_spec(const std::string& text, std::string* error) {
    const auto fail = [&](const std::string& why) {
        *error = "bad fault spec '" + text + "': " + why;
        return std::optional<fault_spec>{};
    };
    fault_spec spec;
    spec.text = text;

    // kind[:params][@trigger]
    const size_t at = text.find('@');
    const std::string head = text.substr(0, at);
    const std::string trigger = at == std::string::npos ? "" : text.substr(at + 1);
    const size_t colon = head.find(':');
    const std::string kind_name = head.substr(0, colon);
    const std::string params = colon == std::string::npos ? "" : head.substr(colon + 1);
    const kind_info* kind = find_kind(kind_name);
    if (!kind) return fail("unknown fault kind '" + kind_name + "' (kinds: " + kind_names() + ")");
    spec.type = kind->type;

    param_values values;
    std::string why = parse_params(*kind, params, colon != std::string::npos, &values);
    if (why.empty() && at != std::string::npos) why = parse_trigger(trigger, &spec.when);
    if (why.empty()) why = apply_params(values, &spec);
    if (!why.empty()) return fail(why);
    return spec;
}

std::string canonical(const fault_spec& s) {
    const kind_info& k = kind_of(s.type);
    std::string out = k.name;
    std::string params;
    const auto add = [&](const std::string& key, const std::string& value) {
        params += (params.empty() ? "" : ",") + key + "=" + value;
    };
    if (s.camera >= 0) add("sensor", s.camera == 0 ? "L" : "R");
    switch (s.type) {
        case fault_type::skew:
            add("lines", std::to_string(s.lines));
            add("pixels", std::to_string(s.pixels));
            break;
        case fault_type::drop_line:
            add("line", std::to_string(s.line));
            break;
        case fault_type::drift:
            add("ppm", std::to_string(s.ppm));
            break;
        case fault_type::glitch:
            add("signal", s.href ? "href" : "vsync");
            add("width", std::to_string(s.width));
            break;
        case fault_type::dark_leak:
            add("level", std::to_string(s.level));
            break;
        case fault_type::stuck_bit:
            add("bit", std::to_string(s.bit));
            add("value", std::to_string(s.value));
            break;
        case fault_type::emif_wait:
            add("cycles", std::to_string(s.cycles));
            add("ce", std::to_string(s.ce));
            break;
        case fault_type::cpu_slow:
            add("factor", format_number(s.factor));
            break;
        default:
            break;
    }
    if (!params.empty()) out += ":" + params;
    if (s.when.kind == trigger_spec::by::frame) out += "@frame=" + std::to_string(s.when.frame);
    if (s.when.kind == trigger_spec::by::ms) out += "@ms=" + format_number(s.when.ms);
    return out;
}

simtime::ticks trigger_tick(const fault_spec& spec, simtime::ticks period) {
    switch (spec.when.kind) {
        case trigger_spec::by::start:
            return 0;
        case trigger_spec::by::ms:
            return static_cast<simtime::ticks>(
                std::llround(spec.when.ms * 1e6 * static_cast<double>(simtime::ticks_per_ns)));
        case trigger_spec::by::frame:
            if (is_sensor_fault(spec.type)) return -1;
            return static_cast<simtime::ticks>(spec.when.frame) * period;
    }
    return 0;
}

void apply(const fault_spec& s, platform::platform_config& config) {
    if (s.type == fault_type::emif_wait) {
        emif::ardy_fault f;
        f.ce = s.ce;
        f.extra_cycles = s.cycles;
        f.from_tick = trigger_tick(s, config.period);
        config.ardy_faults.push_back(f);
        return;
    }
    if (s.type == fault_type::cpu_slow) {
        config.cpu_slow_num = static_cast<uint32_t>(std::llround(s.factor * 1000));
        config.cpu_slow_den = 1000;
        config.cpu_slow_from = trigger_tick(s, config.period);
        return;
    }
    const sensor::fault_trigger when =
        s.when.kind == trigger_spec::by::frame
            ? sensor::fault_trigger::at_frame(s.when.frame,
                                              s.type == fault_type::drop_line ? s.line : 0)
            : sensor::fault_trigger::at_time(trigger_tick(s, config.period));
    sensor::fault f;
    switch (s.type) {
        case fault_type::skew:
            f = sensor::fault::start_skew(when, s.lines, s.pixels, config.profile.line_pclks);
            break;
        case fault_type::drop_line:
            f = sensor::fault::dropped_line(when);
            break;
        case fault_type::drop_frame:
            f = sensor::fault::dropped_frame(when);
            break;
        case fault_type::extra_frame:
            f = sensor::fault::extra_frame(when);
            break;
        case fault_type::drift:
            f = sensor::fault::pclk_drift(when, s.ppm);
            break;
        case fault_type::glitch:
            f = s.href ? sensor::fault::href_glitch(when, s.width)
                       : sensor::fault::vsync_glitch(when, s.width);
            break;
        case fault_type::dark_leak:
            f = sensor::fault::dark_leak(when, s.level);
            break;
        case fault_type::stuck_bit:
            f = sensor::fault::stuck_data_bit(when, s.bit, s.value != 0);
            break;
        case fault_type::dead:
            f = sensor::fault::never_start(when);
            break;
        case fault_type::oe_stuck:
            f = sensor::fault::ignore_oe(when);
            break;
        default:
            return;
    }
    (s.camera == 0 ? config.left_faults : config.right_faults).push_back(f);
}

std::string kinds_listing() {
    std::string out =
        "Fault specs: KIND[:KEY=VALUE,...][@TRIGGER]   (docs/faults.md, contract: "
        "docs/fault-contract.md)\n"
        "  TRIGGER: @frame=N  sensor faults: the sensor's own frame N (frames it started since "
        "power-on);\n"
        "                     emif-wait, cpu-slow: the start of sync period N (N x 24.5 ms)\n"
        "           @ms=T     simulated time T ms (sensor faults: the first pixel clock at or "
        "after "
        "it)\n"
        "           none      from the start (time 0)\n\n";
    for (const kind_info& k : fault_kinds()) {
        out += std::string("  ") + k.name + "  (" + k.hook + ")\n      " + k.doc + "\n";
        for (const param_info& p : k.params) {
            char line[256];
            std::snprintf(line, sizeof line, "      %-8s %-34s %s%s\n", p.name,
                          range_text(p).c_str(), p.default_text ? "default " : "required",
                          p.default_text ? p.default_text : "");
            out += line;
            out += std::string("               ") + p.doc + "\n";
        }
    }
    out +=
        "\nExamples: skew:sensor=R,lines=3@frame=5  drop-line:sensor=L,line=100@frame=7  "
        "drift:sensor=R,ppm=200\n"
        "          glitch:sensor=L,signal=href@ms=130.2  emif-wait:cycles=40@frame=3  "
        "cpu-slow:factor=3@frame=6\n";
    return out;
}

}  // namespace faults
