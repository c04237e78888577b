#include "tb/platform/island/timeline.h"

#include "tb/platform/firmware_report.h"

namespace platform {

const char* event_kind_name(event_kind k) {
    switch (k) {
        case event_kind::oe:
            return "oe";
        case event_kind::irq:
            return "irq";
        case event_kind::sensor_frame:
            return "sensor_frame";
        case event_kind::stage_begin:
            return "stage_begin";
        case event_kind::stage_end:
            return "stage_end";
        case event_kind::firmware:
            return "firmware";
        case event_kind::cpu_sleep:
            return "cpu_sleep";
        case event_kind::cpu_wake:
            return "cpu_wake";
        case event_kind::result:
            return "result";
        case event_kind::fault:
            return "fault";
    }
    return "?";
}

void timeline::insert(simtime::ticks tick, event_kind kind, uint8_t a, uint32_t b, uint32_t c) {
    auto at = m_events.end();
    while (at != m_events.begin() && (at - 1)->tick > tick) --at;
    m_events.insert(at, {tick, kind, a, b, c});
}

bool timeline::in_time_order() const {
    for (size_t i = 1; i < m_events.size(); ++i)
        if (m_events[i].tick < m_events[i - 1].tick) return false;
    return true;
}

uint64_t timeline::hash() const {
    uint64_t h = 1469598103934665603ull;
    for (const timeline_event& e : m_events) {
        const uint64_t words[4] = {static_cast<uint64_t>(e.tick),
                                   static_cast<uint64_t>(e.kind) << 8 | e.a, e.b, e.c};
        h = fnv1a(reinterpret_cast<const uint8_t*>(words), sizeof words, h);
    }
    return h;
}

size_t timeline::count(event_kind k) const {
    size_t n = 0;
    for (const timeline_event& e : m_events) n += e.kind == k;
    return n;
}

namespace {

const char* event_name(const timeline& t, const timeline_event& e) {
    switch (e.kind) {
        case event_kind::stage_begin:
        case event_kind::stage_end:
            return t.stage_name(e.a);
        case event_kind::firmware:
            return platform::report_name(e.a);
        case event_kind::result:
            return t.state_name(e.a);
        default:
            return "";
    }
}

}  // namespace

bool timeline::write_csv(const std::string& path) const {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) return false;
    std::fprintf(f, "tick,time_ns,kind,name,a,b,c\n");
    for (const timeline_event& e : m_events) {
        std::fprintf(f, "%lld,%.3f,%s,%s,%u,%u,%u\n", static_cast<long long>(e.tick),
                     static_cast<double>(e.tick) / simtime::ticks_per_ns, event_kind_name(e.kind),
                     event_name(*this, e), e.a, e.b, e.c);
    }
    return std::fclose(f) == 0;
}

}  // namespace platform
