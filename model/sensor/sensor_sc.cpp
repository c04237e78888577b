#include "model/sensor/sensor_sc.h"

#include <string>

#include "model/time/sc_ticks.h"

namespace sensor {

tick_clock_sc::tick_clock_sc(sc_core::sc_module_name name, const simtime::tick_clock& clock)
    : sc_core::sc_module(name), clk("clk"), m_clock(clock) {
    SC_HAS_PROCESS(tick_clock_sc);
    SC_THREAD(run);
}

void tick_clock_sc::run() {
    simtime::clock_cursor cursor(m_clock);
    bool level = false;
    for (;;) {
        const sc_core::sc_time at = simtime::sc_time_of(cursor.tick());
        if (at > sc_core::sc_time_stamp()) wait(at - sc_core::sc_time_stamp());
        level = !level;
        clk.write(level);
        cursor.advance();
    }
}

sensor_sc::sensor_sc(sc_core::sc_module_name name, const sensor_profile& profile,
                     scene::camera_id camera, frame_source& source, const sensor_config& config)
    : sc_core::sc_module(name),
      mclk("mclk"),
      oe("oe"),
      pclk("pclk"),
      vsync("vsync"),
      href("href"),
      valid("valid"),
      fodd("fodd"),
      data("data"),
      m_core(profile, camera, source, config) {
    SC_HAS_PROCESS(sensor_sc);
    SC_THREAD(run);
}

void sensor_sc::wait_for_edge(simtime::ticks tick) {
    const sc_core::sc_time target = simtime::sc_time_of(tick);
    if (m_core.on_master_clock()) {
        // Always woken by an mclk edge (also the first one, at time 0), so
        // PCLK follows MCLK by exactly one delta cycle on every edge.
        do {
            wait(mclk.value_changed_event());
        } while (sc_core::sc_time_stamp() < target);
        if (sc_core::sc_time_stamp() != target)
            SC_REPORT_ERROR(name(),
                            ("master clock edge at " + sc_core::sc_time_stamp().to_string() +
                             ", the profile's pixel clock needs " + target.to_string())
                                .c_str());
    } else if (target > sc_core::sc_time_stamp()) {
        wait(target - sc_core::sc_time_stamp());
    }
}

void sensor_sc::run() {
    pclk.write(false);
    vsync.write(false);
    href.write(false);
    valid.write(false);
    fodd.write(false);
    data.write(0);
    for (;;) {
        wait_for_edge(m_core.next_rise_tick());
        pclk.write(true);
        const pin_word w = m_core.step(oe.read());
        wait_for_edge(m_core.last_fall_tick());
        pclk.write(false);
        vsync.write(w.vsync());
        href.write(w.href());
        valid.write(w.valid());
        fodd.write(w.fodd());
        data.write(w.data());
    }
}

}  // namespace sensor
