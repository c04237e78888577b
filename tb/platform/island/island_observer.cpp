#include "tb/platform/island/island_observer.h"

namespace platform {

island_observer::island_observer(const island_config& config, emif::emif_async_master& engine,
                                 timeline& events, event_order order)
    : m_engine(engine),
      m_events(events),
      m_order(order),
      m_hash_pins(config.hash_pins),
      m_period(config.period),
      m_end(config.end),
      m_frames(config.profile, config.frame_ring, events),
      m_tracer(config, engine.config().eclk, events, order),
      m_next_boundary(config.period) {
    m_access_seen[0] = engine.stats().accesses[0];
    m_access_seen[1] = engine.stats().accesses[1];
    m_dsp_seen = pack_dsp_pins(engine.pins());
    m_hash.set_initial(pin_group_emif_dsp, m_dsp_seen);
}

void island_observer::interrupt_edges(simtime::ticks t, uint8_t irq) {
    const unsigned rose = irq & ~m_irq & 7u;
    const unsigned fell = m_irq & ~irq & 7u;
    for (int n = 0; n < 3; ++n) {
        if ((rose >> n) & 1u) {
            m_irq_rises[n].push_back(t);
            add_event(t, event_kind::irq, static_cast<uint8_t>(4 + n), 1);
        } else if ((fell >> n) & 1u) {
            add_event(t, event_kind::irq, static_cast<uint8_t>(4 + n), 0);
        }
    }
    m_irq = irq;
    ++m_stats.stops_irq;
}

void island_observer::close_period() {
    const uint64_t busy = m_engine.stats().busy_edges;
    m_current.emif_busy_edges = busy - m_busy_at_boundary;
    m_busy_at_boundary = busy;
    const uint64_t cpu_words = m_engine.stats().words[static_cast<int>(emif::requester::cpu)];
    m_current.cpu_words = cpu_words - m_cpu_words_at_boundary;
    m_cpu_words_at_boundary = cpu_words;
    for (int c = 0; c < 2; ++c) {
        if (m_current.fifo_peak_words[c] > m_fifo_peak_run[c])
            m_fifo_peak_run[c] = m_current.fifo_peak_words[c];
    }
    m_current.eclk_edges = m_stats.eclk_edges - m_eclk_at_boundary;
    m_eclk_at_boundary = m_stats.eclk_edges;
    m_periods.push_back(m_current);
    m_current = period_sample{};
    m_next_boundary += m_period;
}

void island_observer::finish() {
    m_hash.finish();
    m_stats.pin_changes = m_hash.changes();
    m_frames.finish();
    m_tracer.finish(m_end);
}

}  // namespace platform
