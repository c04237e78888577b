// SystemC pin wrappers around the plain C++ cores (library sensor_sc; the
// user links SystemC, e.g. through tb_sc_test_main). The time resolution must
// be 1 fs (tests/support/sc_test_main.cpp): every edge is placed at simtime::to_fs of its
// exact tick, never by adding rounded periods.
#pragma once

#include <cstdint>
#include <systemc>

#include "model/sensor/sensor_core.h"
#include "model/time/ticks.h"

namespace sensor {

// A clock pin driven from a tick_clock: half-edge h at to_fs(half_edge(h)),
// high from each rising edge (even h). The card's master clock is one.
class tick_clock_sc : public sc_core::sc_module {
  public:
    sc_core::sc_out<bool> clk;

    tick_clock_sc(sc_core::sc_module_name name, const simtime::tick_clock& clock);

    const simtime::tick_clock& clock() const { return m_clock; }

  private:
    void run();

    simtime::tick_clock m_clock;
};

// One CMOS sensor with pins: pclk, vsync, href, data[7:0], valid out; oe and
// the master clock in. The same sensor_core as the fast island, so both give
// the same pins (tests/model/test_sensor_pins_sc.cpp proves it).
//
// The pixel clock follows mclk (pclk = mclk / mclk_per_pclk): each edge the
// core expects is waited for on mclk and checked to the femtosecond (a master
// clock that does not match the profile is an SC_ERROR). After a pclk_drift
// fault the sensor runs on its own oscillator and times its edges itself.
// OE is sampled at pclk's rising edge; outputs change at its falling edge.
class sensor_sc : public sc_core::sc_module {
  public:
    sc_core::sc_in<bool> mclk;
    sc_core::sc_in<bool> oe;
    sc_core::sc_out<bool> pclk;
    sc_core::sc_out<bool> vsync;
    sc_core::sc_out<bool> href;
    sc_core::sc_out<bool> valid;
    sc_core::sc_out<bool> fodd;      // frame identity (pin_word::fodd_bit)
    sc_core::sc_out<uint32_t> data;  // data[7:0]; uint32_t as Verilator's --sc ports

    sensor_sc(sc_core::sc_module_name name, const sensor_profile& profile, scene::camera_id camera,
              frame_source& source, const sensor_config& config = {});

    sensor_core& core() { return m_core; }
    const sensor_core& core() const { return m_core; }

  private:
    void run();
    void wait_for_edge(simtime::ticks tick);

    sensor_core m_core;
};

}  // namespace sensor
