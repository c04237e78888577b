// The platform top (docs/platform.md): two sensors -> the daughter card RTL
// -> EMIFA -> the C6416 model running the firmware under test -> 3D track, in
// the arrangement platform_config names (tb/platform/arrangements/), with
// the observers the scoreboard and the budget checker read after the run.
//
//   scene renderer --RGB--> island [ sensor L, sensor R, card (--cc), EMIF engine ]
//                                 |  EXT_INT4..6 (sc_signal)     ^ TLM b_transport
//                                 v                              |
//                           c6416_sc [ CPU thread: firmware on probe_hal, EDMA, L2, SDRAM ]
//
// One platform per process: SystemC elaborates once (docs/design-brief.md "Known traps").
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <systemc>
#include <vector>

#include "model/c6416/c6416_sc.h"
#include "model/emif/emif_async_master.h"
#include "model/emif/emif_tlm_target_sc.h"
#include "model/scene/replay.h"
#include "model/scene/sequence.h"
#include "model/sensor/scene_sources.h"
#include "stereosim/firmware.h"
#include "tb/firmware/plugin.h"
#include "tb/platform/firmware_services.h"
#include "tb/platform/island/island.h"
#include "tb/platform/island/timeline.h"
#include "tb/platform/platform_config.h"
#include "tb/platform/probe_hal.h"
#include "tb/platform/recording_source.h"

namespace platform {

// A pair the EDMA moved into a pair buffer, checked the moment the firmware
// takes it (its pair_captured report): the raw frames in modelled DSP
// memory against the sensors' frames as driven on their pins.
struct captured_pair {
    uint32_t pair = 0;  // the card's PAIRS_OK number copied with it
    int buffer = 0;
    uint32_t address[2] = {};            // its left and right frame in DSP memory (the report's)
    simtime::ticks tick = 0;             // pair_captured report
    simtime::ticks ready = -1;           // FRAME_READY rise of this pair, -1 unknown
    uint32_t verdict = 0;                // VERDICT copied with it
    int64_t sensor_frame[2] = {-1, -1};  // truth index of the sensor frame (by timing)
    uint64_t memory_checksum[2] = {};
    bool sensor_checksum_known[2] = {};
    uint64_t sensor_checksum[2] = {};
    uint64_t differing_pixels[2] = {};  // memory vs sensor frame
    uint8_t differing_bits[2] = {};     // OR of (memory XOR sensor) over the frame
};

// The frames the firmware used for a pair, checked at its FRAMES_USED report
// (docs/fault-contract.md, rule 7): the two frames at the addresses it names
// against the sensors' frames of the pair it names. A pair_processed with no
// FRAMES_USED for its pair since the pair was captured is kept too, with
// `reported` false: rule 7 could not judge it, which is a violation.
struct used_pair {
    uint32_t pair = 0;
    bool reported = false;  // FRAMES_USED came before pair_processed
    bool checked = false;   // the pair was captured and both sensors' checksums are known
    bool matches = false;   // the frames named are the pair's own and were read
    bool read = false;      // memory() covered both named frames since the pair was captured
    uint32_t address[2] = {};
};

// A memory() the firmware asked for (what it reads of DSP memory).
struct memory_read {
    uint32_t address = 0, bytes = 0;
};

class platform_top {
  public:
    explicit platform_top(const platform_config& config);
    ~platform_top();
    platform_top(const platform_top&) = delete;
    platform_top& operator=(const platform_top&) = delete;

    // Simulates up to config.frames sync periods from where the simulation
    // stands (sc_start); then the run is over.
    void run();
    // Simulates up to tick t (no further than the run's end) and pauses: a
    // fault campaign's snapshot point (tb/app/faults/snapshots.h).
    void run_until(simtime::ticks t);
    // Continues the paused run as the run of `config`, which must differ
    // from this platform's (built without faults) only in faults that have
    // not started yet: the sensors' and the bus's are added to the island,
    // the CPU's cycle scale is set. Throws std::invalid_argument if config
    // differs in its length, seed, arrangement, DSK clock, mode, card and
    // firmware settings, pin hash or trace, or has a wire fault.
    void continue_with_faults(const platform_config& config);
    // Called after each simulated sync period with the periods done (the
    // stereosim command's progress line); set before run(). With a hook the
    // run is sc_start'ed period by period, which changes no result (the
    // island syncs at the pause like at any other process's activity).
    void set_progress(std::function<void(int periods_done)> hook) { m_progress = std::move(hook); }

    const platform_config& config() const { return m_config; }
    // The replay the sensors show (config.replay_manifest), or null.
    const scene::replay* replay() const { return m_replay.get(); }
    const scene::sequence& sequence() const { return m_sequence; }
    const recording_source& source() const { return m_source; }
    island& cycle_island() { return *m_island; }
    const island& cycle_island() const { return *m_island; }
    c6416::c6416_sc& cpu() { return *m_cpu; }
    const c6416::c6416_sc& cpu() const { return *m_cpu; }
    const emif::emif_async_master& engine() const { return m_engine; }
    const probe_hal& probe() const { return *m_probe; }
    bool firmware_started() const { return m_probe != nullptr; }
    bool firmware_init_failed() const { return m_init_failed; }
    // The firmware's own line when it refused its configuration.
    const std::string& firmware_init_error() const { return m_init_error; }
    // The firmware under test (the built-in reference unless config.firmware
    // names a plugin) and the recovery policy it was created with.
    const stereosim_fw_descriptor& firmware_descriptor() const { return *m_firmware; }
    const firmware::plugin* firmware_plugin() const { return m_plugin.get(); }
    const stereosim_fw_policy& firmware_policy() const { return m_policy; }
    const timeline& events() const { return m_timeline; }
    // An injected fault's onset on the timeline (tb/app/faults, after the run).
    void mark_fault(simtime::ticks tick, uint8_t index, uint32_t type, uint32_t frame) {
        m_timeline.insert(tick, event_kind::fault, index, type, frame);
    }
    const std::vector<captured_pair>& captured() const { return m_captured; }
    const std::vector<used_pair>& used_pairs() const { return m_used; }
    // The run's end (config.frames periods) and the host time run() took.
    simtime::ticks end_tick() const { return m_end_tick; }
    double wall_s() const { return m_wall_s; }

    // The sensor frame (truth index) whose last active pixel is the latest
    // before `tick`, or -1.
    int64_t frame_before(int camera, simtime::ticks tick) const;

  private:
    // sc_start up to tick t (the run's end at most), if not there yet.
    void advance_to(simtime::ticks t);
    void firmware(c6416::cpu_port& cpu);
    void on_firmware_event(const fw_event& e);
    void check_captured(captured_pair& pair);
    void check_used(const stereosim_event& frames_used);
    void check_processed(uint32_t pair);

    platform_config m_config;
    scene::sequence m_sequence;
    recording_source m_source;
    emif::emif_async_master m_engine;
    timeline m_timeline;
    std::unique_ptr<c6416::c6416_sc> m_cpu;
    std::unique_ptr<emif::emif_tlm_target> m_target;
    std::unique_ptr<island> m_island;
    sc_core::sc_signal<bool> m_int[4];
    std::unique_ptr<probe_hal> m_probe;
    std::unique_ptr<firmware::plugin> m_plugin;  // config.firmware, or null
    const stereosim_fw_descriptor* m_firmware = nullptr;
    std::unique_ptr<firmware_services> m_services;
    void* m_instance = nullptr;  // the firmware's, between create() and destroy()
    stereosim_fw_policy m_policy{};
    std::vector<double> m_key_values;  // the firmware's keys, as create() read them
    bool m_init_failed = false;
    std::string m_init_error;
    std::vector<captured_pair> m_captured;
    std::vector<used_pair> m_used;
    std::vector<memory_read> m_reads;  // the firmware's memory() since the last pair_captured
    simtime::ticks m_end_tick = 0;
    double m_wall_s = 0.0;
    std::function<void(int)> m_progress;
    std::unique_ptr<scene::replay> m_replay;  // config.replay_manifest
    std::unique_ptr<sensor::replay_source> m_replay_source;
};

}  // namespace platform
