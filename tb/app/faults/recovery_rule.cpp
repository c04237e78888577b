#include "tb/app/faults/recovery_rule.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace faults {

namespace {

using simtime::ticks;

std::string ms_text(ticks t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f ms",
                  static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6));
    return text;
}

bool running(uint32_t state) {
    return state == static_cast<uint32_t>(card_state::wait_vsync) ||
           state == static_cast<uint32_t>(card_state::run);
}

// The last tick of a sorted list at or before t, or -1.
ticks last_at_or_before(const std::vector<ticks>& sorted, ticks t) {
    const auto it = std::upper_bound(sorted.begin(), sorted.end(), t);
    return it == sorted.begin() ? -1 : *(it - 1);
}

bool any_in(const std::vector<ticks>& sorted, ticks after, ticks until) {
    const auto it = std::upper_bound(sorted.begin(), sorted.end(), after);
    return it != sorted.end() && *it <= until;
}

class recovery_judge {
  public:
    explicit recovery_judge(const recovery_inputs& in) : m_in(in) {
        m_events = in.sync_errors;
        m_events.insert(m_events.end(), in.frame_readies.begin(), in.frame_readies.end());
        m_events.insert(m_events.end(), in.overflows.begin(), in.overflows.end());
        std::sort(m_events.begin(), m_events.end());
    }

    recovery_observation judge() {
        card_actions();
        firmware_actions();
        watchdog_reports();
        silences();
        overflows();
        return m_r;
    }

  private:
    void note(const std::string& line) {
        if (m_r.unexplained.size() < 8) m_r.unexplained.push_back(line);
    }

    // STATUS.STATE in force at t (the last change at or before it).
    uint32_t state_at(ticks t) const {
        uint32_t state = static_cast<uint32_t>(card_state::idle);
        for (const tick_value& s : m_in.card_states) {
            if (s.tick > t) break;
            state = s.value;
        }
        return state;
    }

    // Whether the start a failure at t belongs to passed a check before it:
    // the card checks at its origin (the first VSYNC rise of either sensor
    // after OE rose) + k frames, so a failure more than 1.5 frames after the
    // origin came after at least one passing check.
    bool passed_before(ticks t) const {
        const ticks oe = last_at_or_before(m_in.oe_rises, t);
        if (oe < 0 || m_in.card_frame <= 0) return false;
        const auto origin = std::lower_bound(m_in.vsync_rises.begin(), m_in.vsync_rises.end(), oe);
        return origin != m_in.vsync_rises.end() && *origin < t &&
               2 * (t - *origin) > 3 * m_in.card_frame;
    }

    // Whether the card passed through IDLE in (after, until]: IDLE clears its
    // count of failed checks (rtl/oe_control.v).
    bool idle_in(ticks after, ticks until) const {
        for (const tick_value& s : m_in.card_states)
            if (s.tick > after && s.tick <= until &&
                s.value == static_cast<uint32_t>(card_state::idle))
                return true;
        return false;
    }

    // Each SYNC_ERROR pulse against the card's reaction (a restart or
    // HARD_ERROR a little before the pulse) and the failed checks in a row.
    void card_actions() {
        struct action {
            ticks tick;
            uint32_t state;
            bool matched;
        };
        std::vector<action> actions;
        uint32_t before = static_cast<uint32_t>(card_state::idle);
        for (const tick_value& s : m_in.card_states) {
            const bool acted = s.value == static_cast<uint32_t>(card_state::oe_low) ||
                               s.value == static_cast<uint32_t>(card_state::hard_error);
            if (acted && running(before)) actions.push_back({s.tick, s.value, false});
            before = s.value;
        }
        const int limit = static_cast<int>(m_in.retry_limit);
        int streak = 0;
        ticks previous = -1;
        for (ticks t : m_in.sync_errors) {
            ++m_r.failed_checks;
            if (idle_in(previous, t) || passed_before(t)) streak = 0;
            previous = t;
            m_r.longest_streak = std::max(m_r.longest_streak, ++streak);
            action* reaction = nullptr;
            for (action& a : actions)
                if (!a.matched && a.tick <= t && a.tick >= t - reaction_window) reaction = &a;
            if (reaction == nullptr) {
                ++m_r.checks_without_action;
                note("a SYNC_ERROR at " + ms_text(t) +
                     " the card did not act on (no restart, no HARD_ERROR)");
                continue;
            }
            reaction->matched = true;
            const bool hard = reaction->state == static_cast<uint32_t>(card_state::hard_error);
            const std::string count = std::to_string(streak) + " failed check(s) in a row";
            const std::string due = " (RETRY_LIMIT + 1 = " + std::to_string(limit + 1) + ")";
            if (hard && streak <= limit) {
                ++m_r.hard_errors_early;
                note("card HARD_ERROR at " + ms_text(reaction->tick) + " after " + count + due);
            } else if (!hard && streak > limit) {
                ++m_r.hard_errors_missed;
                note("card restart at " + ms_text(reaction->tick) + " after " + count +
                     ": HARD_ERROR was due" + due);
            }
        }
        for (const action& a : actions) {
            const bool hard = a.state == static_cast<uint32_t>(card_state::hard_error);
            m_r.card_hard_errors += hard;
            m_r.card_restarts += !hard;
            if (a.matched) continue;
            ++m_r.actions_without_check;
            note(std::string("card ") + (hard ? "HARD_ERROR" : "restart") + " at " +
                 ms_text(a.tick) + " with no SYNC_ERROR pulse (no failed check on its pins)");
        }
    }

    // The card's silence before t: no interrupt pulse, no OE raise by the
    // DSP since `raise`.
    ticks quiet_since(ticks t, ticks raise) const {
        return std::max(last_at_or_before(m_events, t), raise);
    }

    bool fault_in_effect(ticks t) const {
        for (ticks onset : m_in.fault_onsets)
            if (onset <= t) return true;
        return false;
    }

    // A firmware action: ENABLE 1 -> 0 at w0 (a re-arm if ENABLE 1 follows,
    // else the give-up), since the raise at `raise`.
    void judge_action(ticks w0, ticks raise, bool rearm) {
        const std::string what = std::string(rearm ? "re-arm" : "give-up") + " at " + ms_text(w0);
        const auto cause = [&](const char* name) {
            if (!rearm) m_r.give_up_cause = name;
        };
        if (state_at(w0) == static_cast<uint32_t>(card_state::hard_error))
            return cause("hard_error");
        if (m_in.rearm_on_overflow && any_in(m_in.overflows, raise, w0)) return cause("overflow");
        if (m_in.rearm_on_every_sync_error && any_in(m_in.sync_errors, raise, w0))
            return cause("sync_error");
        const ticks quiet = quiet_since(w0, raise);
        if (m_in.watchdog > 0 && w0 - quiet >= m_in.watchdog - watchdog_slack) {
            cause("watchdog");
            ++m_r.watchdog_firings;
            if (!fault_in_effect(w0)) {
                ++m_r.unexplained_silences;
                note("the card was silent from " + ms_text(quiet) + " to the watchdog's " + what +
                     " with no fault in effect");
            }
            return;
        }
        ++m_r.unexplained_rearms;
        note("a firmware " + what + " with no cause on the card's pins since its raise at " +
             ms_text(raise) + " (no HARD_ERROR, no OVERFLOW" +
             (m_in.rearm_on_every_sync_error ? ", no SYNC_ERROR" : "") + ", card or raise " +
             ms_text(w0 - quiet) + " before: not a silent watchdog period)");
    }

    void firmware_actions() {
        const std::vector<tick_value>& writes = m_in.enable_writes;
        bool enabled = false, booted = false;
        ticks raise = 0;
        for (size_t i = 0; i < writes.size() && writes[i].tick < m_in.end; ++i) {
            const bool on = (writes[i].value & 1u) != 0;
            if (on && !enabled) {
                m_r.firmware_rearms += booted;
                booted = true;
                raise = writes[i].tick;
            } else if (!on && enabled) {
                bool rearm = false;
                for (size_t k = i + 1; k < writes.size() && writes[k].tick < m_in.end; ++k)
                    if ((writes[k].value & 1u) != 0) rearm = true;
                judge_action(writes[i].tick, raise, rearm);
            }
            enabled = on;
        }
    }

    std::vector<ticks> raises() const { return enable_raises(m_in.enable_writes); }

    // The firmware's own watchdog reports: each after a whole period of silence.
    void watchdog_reports() {
        const std::vector<ticks> raised = raises();
        for (ticks f : m_in.watchdog_reports) {
            if (f >= m_in.end) continue;
            const ticks quiet = quiet_since(f, last_at_or_before(raised, f));
            if (m_in.watchdog > 0 && f - quiet >= m_in.watchdog - watchdog_slack) continue;
            ++m_r.early_watchdogs;
            note("a watchdog report at " + ms_text(f) + " " + ms_text(f - quiet) +
                 " after the card's last event or OE raise (period " + ms_text(m_in.watchdog) +
                 ")");
        }
    }

    // A silent card with ENABLE 1 must be re-armed within two watchdog
    // periods (the tick that sees the last event, then the one that sees
    // none) plus the firmware's service time.
    void silences() {
        if (m_in.watchdog <= 0) return;
        enum class mark : uint8_t { event, enable_on, enable_off };
        std::vector<std::pair<ticks, mark>> marks;
        for (ticks t : m_events) marks.emplace_back(t, mark::event);
        // Only ENABLE's changes: a CTRL write that keeps ENABLE 1 is no action.
        bool written = false;
        for (const tick_value& w : m_in.enable_writes) {
            const bool on = (w.value & 1u) != 0;
            if (on != written) marks.emplace_back(w.tick, on ? mark::enable_on : mark::enable_off);
            written = on;
        }
        const ticks stop = std::min(m_in.end, m_in.give_up);
        marks.emplace_back(stop, mark::enable_off);
        std::stable_sort(marks.begin(), marks.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        const ticks bound = 2 * m_in.watchdog + m_in.service + watchdog_slack;
        bool enabled = false;
        ticks previous = -1;
        for (const auto& [tick, kind] : marks) {
            if (tick > stop) break;
            if (enabled && previous >= 0 && tick - previous > bound) {
                ++m_r.missed_watchdogs;
                note("the card was silent with ENABLE 1 from " + ms_text(previous) + " for " +
                     ms_text(tick - previous) + ": the watchdog (" + ms_text(m_in.watchdog) +
                     ") did not act within 2 periods");
            }
            if (kind != mark::event) enabled = kind == mark::enable_on;
            previous = tick;
        }
    }

    void overflows() {
        for (ticks t : m_in.overflows) {
            bool explained = false;
            for (ticks onset : m_in.bus_fault_onsets) explained |= onset <= t;
            if (explained) continue;
            ++m_r.unexplained_overflows;
            note("an OVERFLOW at " + ms_text(t) + " with no bus fault in effect");
        }
    }

    const recovery_inputs& m_in;
    std::vector<ticks> m_events;  // every card interrupt pulse, sorted
    recovery_observation m_r;
};

}  // namespace

recovery_observation judge_recovery(const recovery_inputs& in) {
    return recovery_judge(in).judge();
}

std::vector<ticks> enable_raises(const std::vector<tick_value>& writes) {
    std::vector<ticks> raises;
    bool enabled = false;
    for (const tick_value& w : writes) {
        const bool on = (w.value & 1u) != 0;
        if (on && !enabled) raises.push_back(w.tick);
        enabled = on;
    }
    return raises;
}

}  // namespace faults
