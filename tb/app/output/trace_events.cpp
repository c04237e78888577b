#include "tb/app/output/trace_events.h"

#include "tb/app/faults/fault_spec.h"
#include "tb/platform/firmware_report.h"

#include <nlohmann/json.hpp>

namespace output {

using nlohmann::json;
using platform::event_kind;
using simtime::ticks;

namespace {

enum track : int { cpu = 1, edma = 2, card = 3, sensors = 4 };

double us_of(ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1000.0);
}

json complete(const char* name, const char* cat, int tid, ticks begin, ticks end) {
    return json{{"name", name},
                {"cat", cat},
                {"ph", "X"},
                {"pid", 1},
                {"tid", tid},
                {"ts", us_of(begin)},
                {"dur", us_of(end - begin)}};
}

json instant(const std::string& name, const char* cat, int tid, ticks t) {
    return json{{"name", name}, {"cat", cat}, {"ph", "i"},     {"s", "t"},
                {"pid", 1},     {"tid", tid}, {"ts", us_of(t)}};
}

json thread_name(int tid, const char* name) {
    return json{
        {"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", tid}, {"args", {{"name", name}}}};
}

const char* const irq_names[3] = {"EXT_INT4 FRAME_READY", "EXT_INT5 SYNC_ERROR",
                                  "EXT_INT6 OVERFLOW"};

// The pair each firmware stage worked on: the pair of the next
// pair_processed report; a capture stage's: the next pair_captured (it ends
// just before that report).
struct stage_pairs {
    std::vector<uint32_t> next_processed, next_captured;  // per timeline index

    explicit stage_pairs(const std::vector<platform::timeline_event>& tl)
        : next_processed(tl.size() + 1, 0), next_captured(tl.size() + 1, 0) {
        for (size_t i = tl.size(); i-- > 0;) {
            next_processed[i] = next_processed[i + 1];
            next_captured[i] = next_captured[i + 1];
            if (tl[i].kind != event_kind::firmware) continue;
            if (tl[i].a == STEREOSIM_EV_PAIR_PROCESSED) next_processed[i] = tl[i].b;
            if (tl[i].a == STEREOSIM_EV_PAIR_CAPTURED) next_captured[i] = tl[i].b;
        }
    }
    // The firmware's first stage is its capture (the ABI's order): its pair
    // is the next captured one, every other stage's the next processed one.
    uint32_t of(int stage, size_t i) const {
        return stage == 0 ? next_captured[i] : next_processed[i];
    }
};

// The timeline's events as trace events, in timeline order: spans (stages,
// sleeps, OE high) close at their end event, instants as they come.
class timeline_tracks {
  public:
    timeline_tracks(json& events, const platform::timeline& tl)
        : m_events(events), m_timeline(tl), m_pairs(tl.events()) {}

    void add(size_t i, const platform::timeline_event& e) {
        switch (e.kind) {
            case event_kind::stage_begin:
                m_stage_begin = e.tick;
                break;
            case event_kind::stage_end:
                stage_end(i, e);
                break;
            case event_kind::cpu_sleep:
                m_sleep_begin = e.tick;
                break;
            case event_kind::cpu_wake:
                cpu_wake(e);
                break;
            case event_kind::firmware:
                firmware(e);
                break;
            case event_kind::irq:
                if (e.b == 1 && e.a >= 4 && e.a <= 6)
                    m_events.push_back(instant(irq_names[e.a - 4], "interrupt", card, e.tick));
                break;
            case event_kind::oe:
                oe(e);
                break;
            case event_kind::sensor_frame:
                m_events.push_back(
                    instant(e.a == 0 ? "VSYNC L" : "VSYNC R", "frame", sensors, e.tick));
                break;
            case event_kind::fault:
                fault(e);
                break;
            default:  // results: in report.json
                break;
        }
    }

    // Spans still open at the end of the run end there.
    void close(ticks end) {
        if (m_sleep_begin >= 0)
            m_events.push_back(complete("sleep", "idle", cpu, m_sleep_begin, end));
        if (m_oe_begin >= 0) m_events.push_back(complete("OE high", "oe", card, m_oe_begin, end));
    }

  private:
    void stage_end(size_t i, const platform::timeline_event& e) {
        if (m_stage_begin < 0) return;
        json x = complete(m_timeline.stage_name(e.a), "stage", cpu, m_stage_begin, e.tick);
        x["args"] = {{"cycles", e.b}, {"pair", m_pairs.of(e.a, i)}};
        m_events.push_back(x);
        m_stage_begin = -1;
    }

    void cpu_wake(const platform::timeline_event& e) {
        if (m_sleep_begin >= 0)
            m_events.push_back(complete("sleep", "idle", cpu, m_sleep_begin, e.tick));
        m_sleep_begin = -1;
        m_events.push_back(instant(e.a == 255 ? std::string("stop") : "INT" + std::to_string(e.a),
                                   "interrupt", cpu, e.tick));
    }

    void firmware(const platform::timeline_event& e) {
        json x = instant(platform::report_name(e.a), "firmware", cpu, e.tick);
        x["args"] = {{"pair", e.b}, {"value", e.c}};
        m_events.push_back(x);
    }

    void oe(const platform::timeline_event& e) {
        if (e.a == 1) {
            m_oe_begin = e.tick;
        } else if (m_oe_begin >= 0) {
            m_events.push_back(complete("OE high", "oe", card, m_oe_begin, e.tick));
            m_oe_begin = -1;
        }
    }

    // An injected fault's onset (tb/app/faults, docs/faults.md).
    void fault(const platform::timeline_event& e) {
        json x = instant(
            std::string("fault ") + faults::fault_type_name(static_cast<faults::fault_type>(e.b)),
            "fault", sensors, e.tick);
        x["args"] = {{"index", e.a}, {"frame", e.c}};
        m_events.push_back(x);
    }

    json& m_events;
    const platform::timeline& m_timeline;
    const stage_pairs m_pairs;
    ticks m_stage_begin = -1, m_sleep_begin = -1, m_oe_begin = -1;
};

void add_track_names(json& events) {
    events.push_back(
        json{{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"args", {{"name", "stereosim"}}}});
    events.push_back(thread_name(cpu, "CPU (firmware)"));
    events.push_back(thread_name(edma, "EDMA"));
    events.push_back(thread_name(card, "card"));
    events.push_back(thread_name(sensors, "sensors"));
}

// EDMA: per FRAME_READY, a capture chain up to its last burst; the bursts.
void add_edma_track(json& events, const platform::platform_top& top, ticks end) {
    const std::vector<ticks>& ready = top.cycle_island().irq_rises(0);
    const std::vector<ticks>& bursts = top.cycle_island().edma_completions();
    for (size_t p = 0; p < ready.size(); ++p) {
        const ticks next = p + 1 < ready.size() ? ready[p + 1] : end;
        ticks last = -1;
        for (ticks t : bursts)
            if (t > ready[p] && t <= next) last = t;
        if (last < 0) continue;
        json x = complete("capture", "edma", edma, ready[p], last);
        x["args"] = {{"pair", p + 1}};
        events.push_back(x);
    }
    for (ticks t : bursts) events.push_back(instant("burst", "edma", edma, t));
}

}  // namespace

std::string trace_events_json(const platform::platform_top& top) {
    json events = json::array();
    add_track_names(events);
    const ticks end = top.end_tick();

    // CPU (stages, sleeps, interrupts taken, reports), card and sensors.
    const std::vector<platform::timeline_event>& tl = top.events().events();
    timeline_tracks tracks(events, top.events());
    for (size_t i = 0; i < tl.size(); ++i) tracks.add(i, tl[i]);
    tracks.close(end);

    add_edma_track(events, top, end);

    json doc{{"traceEvents", events},
             {"displayTimeUnit", "ns"},
             {"otherData",
              {{"generator", "stereosim (tb/app/output/trace_events.cpp)"},
               {"time_base", "simulated time; 1 tick = 1/18 ns"}}}};
    return doc.dump() + "\n";
}

}  // namespace output
