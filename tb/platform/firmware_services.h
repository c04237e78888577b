// The platform's side of the firmware ABI (docs/firmware-abi.md): the
// services table a firmware plugin calls, served by the probe HAL over the
// C6416 model, so that a firmware behind the ABI is observed exactly as the
// platform observes any firmware (charges, bus accesses, interrupts,
// reports). Its events and results are all the platform reads of it.
#pragma once

#include "stereosim/firmware.h"
#include "tb/platform/probe_hal.h"

namespace platform {

class firmware_services {
  public:
    // A firmware declaring `stage_count` stages and `state_count` tracker
    // states: a charge, stage or result outside them ends the run
    // (firmware_crash.h, firmware_broke_abi).
    firmware_services(probe_hal& probe, uint32_t stage_count, uint32_t state_count);
    firmware_services(const firmware_services&) = delete;
    firmware_services& operator=(const firmware_services&) = delete;

    const stereosim_services& table() const { return m_table; }

    probe_hal& probe() const { return m_probe; }
    uint32_t stage(uint32_t s) const;  // s, if the firmware declared it
    uint32_t state(uint32_t s) const;

  private:
    probe_hal& m_probe;
    uint32_t m_stage_count, m_state_count;
    stereosim_services m_table{};
};

}  // namespace platform
