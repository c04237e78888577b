#include "tb/platform/platform.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "model/c6416/c6416_regs.h"
#include "model/time/sc_ticks.h"
#include "tb/firmware/builtin.h"
#include "tb/platform/arrangements/fast/fast_island.h"
#include "tb/platform/arrangements/pins/pins_island.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/firmware_crash.h"

namespace platform {

namespace {

c6416::c6416_config cpu_config(const platform_config& config) {
    c6416::c6416_config c;
    c.dsk = config.dsk;
    c.sdram_over_emifa = true;
    c.replay_sdram_traffic = config.sdram_traffic_on_bus;
    return c;
}

island_config make_island_config(const platform_config& config) {
    island_config c;
    c.profile = config.profile;
    c.sensor[0].seed = config.left_seed();
    c.sensor[1].seed = config.right_seed();
    for (sensor::sensor_config& s : c.sensor) s.noise = config.sensor_noise;
    c.faults[0] = config.left_faults;
    c.faults[1] = config.right_faults;
    c.wire = config.wire;
    c.ardy_faults = config.ardy_faults;
    c.pclk = simtime::tick_clock(config.profile.mclk_period);
    c.quantum = config.quantum;
    c.period = config.period;
    c.hash_pins = config.hash_pins;
    c.trace = config.trace;
    c.trace_window = config.trace_window;
    c.end = config.period * config.frames;
    return c;
}

}  // namespace

platform_top::platform_top(const platform_config& config)
    : m_config(config),
      m_sequence(config.scenario),
      m_source(m_sequence.scene_renderer()),
      m_engine(engine_config(config)) {
    // Throws std::runtime_error with the loader's one line for a plugin it
    // cannot run (docs/firmware-abi.md).
    if (!config.firmware.empty()) {
        std::string error;
        m_plugin = firmware::plugin::load(config.firmware, &error);
        if (!m_plugin) throw std::runtime_error(error);
        m_firmware = &m_plugin->descriptor();
    } else {
        m_firmware = &::firmware::builtin();
    }
    m_timeline.set_firmware_names(
        {m_firmware->stage_names, m_firmware->stage_names + m_firmware->stage_count},
        {m_firmware->tracker_state_names,
         m_firmware->tracker_state_names + m_firmware->tracker_state_count});
    if (!config.replay_manifest.empty()) {
        // Throws std::runtime_error naming the file for a bad manifest or image.
        m_replay = std::make_unique<scene::replay>(
            config.replay_manifest, config.profile.active_cols, config.profile.active_rows);
        m_replay_source = std::make_unique<sensor::replay_source>(*m_replay);
        m_source.use_replay(m_replay_source.get());
    }
    m_cpu = std::make_unique<c6416::c6416_sc>("dsk", cpu_config(config));
    m_target = std::make_unique<emif::emif_tlm_target>("emifa", m_engine);
    if (config.arrangement == arrangement_kind::pins) {
        m_island = pins::make_pins_island("island", make_island_config(config), m_source, m_engine,
                                          m_timeline);
    } else {
        m_island = fast::make_fast_island("island", make_island_config(config), m_source, m_engine,
                                          m_timeline);
    }
    m_engine.set_sdram_storage(m_cpu->sdram_storage(), m_cpu->sdram_storage_bytes());
    // Injected CPU faults (tb/app/faults, docs/faults.md); the bus's ARDY faults
    // are the board glue's, in the island (model/emif/ardy_glue.h).
    if (config.cpu_slow_num != config.cpu_slow_den)
        m_cpu->set_cycle_scale(config.cpu_slow_num, config.cpu_slow_den,
                               simtime::sc_time_of(config.cpu_slow_from));
    m_cpu->emifa_cpu.bind(m_target->cpu);
    m_cpu->emifa_edma.bind(m_target->edma);
    m_cpu->set_emifa_register_observer([this](uint32_t address, uint32_t value) {
        for (int ce = 0; ce < emif::ce_count; ++ce) {
            if (address == c6416::emifa::cectl(ce)) m_engine.set_cectl(ce, value);
        }
    });
    m_island->ext_int4.bind(m_int[0]);
    m_island->ext_int5.bind(m_int[1]);
    m_island->ext_int6.bind(m_int[2]);
    m_cpu->ext_int4.bind(m_int[0]);
    m_cpu->ext_int5.bind(m_int[1]);
    m_cpu->ext_int6.bind(m_int[2]);
    m_cpu->ext_int7.bind(m_int[3]);  // not connected on the card: stays low
    m_cpu->set_firmware([this](c6416::cpu_port& cpu) { firmware(cpu); });
}

platform_top::~platform_top() {
    // A run that ended with the firmware still in its loop (the usual case:
    // the simulation stops, the CPU thread never resumes) leaves its instance.
    if (m_instance != nullptr) m_firmware->destroy(m_instance);
}

void platform_top::firmware(c6416::cpu_port& cpu) {
    // Kernels priced for this DSK's clocks (SDRAM stalls depend on the CPU /
    // EMIF ratio, model/c64x/cost_model.h) and compiled-C factor.
    m_probe = std::make_unique<probe_hal>(cpu, m_timeline, cost_model_of(m_config));
    m_probe->set_event_hook([this](const fw_event& e) { on_firmware_event(e); });
    m_probe->set_memory_hook([this](uint32_t address, uint32_t bytes) {
        m_reads.push_back({address, bytes});
    });
    m_probe->start();
    // The firmware behind the ABI: it sees the board, its key values and the
    // services; the platform sees its reports.
    m_services = std::make_unique<firmware_services>(*m_probe, m_firmware->stage_count,
                                                     m_firmware->tracker_state_count);
    const stereosim_board board = board_of(m_config);
    // A member, not a local: the simulation usually stops with this thread
    // suspended in run(), so its stack never unwinds.
    m_key_values = plugin_values(*m_firmware, m_config);
    char error[256] = "";
    m_probe->set_stage_names(m_firmware->stage_names, static_cast<int>(m_firmware->stage_count));
    firmware_entered(0, -1, m_firmware->stage_names, static_cast<int>(m_firmware->stage_count));
    m_instance =
        m_firmware->create(&m_services->table(), &board, m_key_values.data(), error, sizeof error);
    firmware_left();
    if (m_instance == nullptr) {
        m_init_failed = true;
        m_init_error = error;
        return;
    }
    m_firmware->policy(m_instance, &m_policy);
    // The CPU thread starts the firmware at time 0.
    firmware_entered(0, -1, m_firmware->stage_names, static_cast<int>(m_firmware->stage_count));
    m_firmware->run(m_instance);
    m_probe->halted();
    firmware_left();
    m_firmware->destroy(m_instance);
    m_instance = nullptr;
}

void platform_top::advance_to(simtime::ticks t) {
    const sc_core::sc_time until =
        simtime::sc_time_of(std::min(t, m_config.period * m_config.frames));
    if (until > sc_core::sc_time_stamp()) sc_core::sc_start(until - sc_core::sc_time_stamp());
}

void platform_top::run_until(simtime::ticks t) {
    const auto wall0 = std::chrono::steady_clock::now();
    advance_to(t);
    m_wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
}

void platform_top::continue_with_faults(const platform_config& config) {
    // What the snapshot's run was built with must be the continuation's (the
    // campaign groups runs whose options differ only in --fault; these are
    // the settings a fault run could plausibly differ in).
    const platform_config& c = m_config;
    const bool same_run =
        config.frames == c.frames && config.seed == c.seed && config.arrangement == c.arrangement &&
        config.dsk.cpu_hz == c.dsk.cpu_hz && config.firmware == c.firmware &&
        config.firmware_settings == c.firmware_settings &&
        config.card_retry_limit == c.card_retry_limit && config.hash_pins == c.hash_pins &&
        config.trace == c.trace && !config.wire.enabled && c.left_faults.empty() &&
        c.right_faults.empty() && c.ardy_faults.empty() && c.cpu_slow_num == c.cpu_slow_den;
    if (!same_run)
        throw std::invalid_argument(
            "a snapshot continues only the run it was taken from, with faults added");
    const std::vector<sensor::fault> sensor_faults[2] = {config.left_faults, config.right_faults};
    m_island->add_late_faults(sensor_faults, config.ardy_faults);
    if (config.cpu_slow_num != config.cpu_slow_den)
        m_cpu->set_cycle_scale(config.cpu_slow_num, config.cpu_slow_den,
                               simtime::sc_time_of(config.cpu_slow_from));
    m_config = config;
}

void platform_top::run() {
    const auto wall0 = std::chrono::steady_clock::now();
    m_end_tick = m_config.period * m_config.frames;
    if (!m_progress) {
        advance_to(m_end_tick);
    } else {
        for (int done = 1; done <= m_config.frames; ++done) {
            advance_to(m_config.period * done);
            m_progress(done);
        }
    }
    m_island->finish();
    // Host time of the whole run, a snapshot's prefix (run_until) included.
    m_wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
}

int64_t platform_top::frame_before(int camera, simtime::ticks tick) const {
    const std::vector<sensor::frame_truth>& truth = m_island->sensor(camera).truth();
    // A frame in its first active line has its first active pixel but no
    // last one yet (last_active_tick 0): not a frame before `tick`, however
    // late this is asked (a slowed CPU takes a pair long after it came).
    for (size_t i = truth.size(); i-- > 0;) {
        const sensor::frame_truth& t = truth[i];
        if (t.have_active && t.last_active_tick >= t.first_active_tick && t.last_active_tick < tick)
            return static_cast<int64_t>(i);
    }
    return -1;
}

void platform_top::on_firmware_event(const fw_event& e) {
    if (e.event.kind == STEREOSIM_EV_FRAMES_USED) check_used(e.event);
    if (e.event.kind == STEREOSIM_EV_PAIR_PROCESSED) check_processed(e.event.pair);
    if (e.event.kind != STEREOSIM_EV_PAIR_CAPTURED) return;
    captured_pair p;
    p.pair = e.event.pair;
    p.buffer = static_cast<int>(e.event.detail);
    p.address[0] = e.event.left;
    p.address[1] = e.event.right;
    p.verdict = e.event.value;
    p.tick = e.tick;
    check_captured(p);
    m_captured.push_back(p);
    m_reads.clear();  // the firmware's reads of this pair start now
}

// Pair identity at the point of use (docs/fault-contract.md, rule 7): the
// frames at the addresses the report names, as they are when the pipeline
// reads them, against the sensors' frames of the pair it names.
void platform_top::check_used(const stereosim_event& frames_used) {
    used_pair u;
    u.pair = frames_used.pair;
    u.reported = true;
    u.address[0] = frames_used.left;
    u.address[1] = frames_used.right;
    // The pair named is the one captured last (searched from the end: the
    // run's every pair is in the list).
    const captured_pair* named = nullptr;
    for (auto c = m_captured.rbegin(); c != m_captured.rend() && !named; ++c)
        if (c->pair == u.pair) named = &*c;
    const uint32_t bytes =
        static_cast<uint32_t>(m_island->frame_width() * m_island->frame_height());
    const uint8_t* left = m_probe->peek(u.address[0], bytes);
    const uint8_t* right = m_probe->peek(u.address[1], bytes);
    if (named && named->sensor_checksum_known[0] && named->sensor_checksum_known[1]) {
        u.checked = true;
        u.matches = left && right && fnv1a(left, bytes) == named->sensor_checksum[0] &&
                    fnv1a(right, bytes) == named->sensor_checksum[1];
    }
    m_used.push_back(u);
}

// At pair_processed: the frames named must be frames the firmware read
// (memory() since the pair was captured), or the report names frames the
// pipeline did not use; a pair whose frames were never named is kept
// unreported.
void platform_top::check_processed(uint32_t pair) {
    const uint32_t bytes =
        static_cast<uint32_t>(m_island->frame_width() * m_island->frame_height());
    const auto was_read = [&](uint32_t address) {
        for (const memory_read& r : m_reads)
            if (r.address <= address && uint64_t{address} + bytes <= uint64_t{r.address} + r.bytes)
                return true;
        return false;
    };
    // Its FRAMES_USED, if any, is among the last entries (pair numbers rise).
    for (auto u = m_used.rbegin(); u != m_used.rend() && u->pair >= pair; ++u) {
        if (u->pair != pair || !u->reported) continue;
        u->read = was_read(u->address[0]) && was_read(u->address[1]);
        u->matches = u->matches && u->read;
        return;
    }
    used_pair u;
    u.pair = pair;
    m_used.push_back(u);
}

// Data path integrity (docs/platform.md): the raw frames as they landed in
// the pair buffer against the active pixels the sensors drove.
void platform_top::check_captured(captured_pair& p) {
    const std::vector<simtime::ticks>& ready = m_island->irq_rises(0);
    if (p.pair >= 1 && p.pair <= ready.size()) p.ready = ready[p.pair - 1];
    const uint32_t bytes =
        static_cast<uint32_t>(m_island->frame_width() * m_island->frame_height());
    for (int c = 0; c < 2; ++c) {
        // Both frames at one address: the report named none.
        if (p.address[0] == p.address[1]) break;
        const uint8_t* memory = m_probe->peek(p.address[c], bytes);
        if (!memory) continue;
        p.memory_checksum[c] = fnv1a(memory, bytes);
        if (p.ready < 0) continue;
        p.sensor_frame[c] = frame_before(c, p.ready);
        if (p.sensor_frame[c] < 0) continue;
        const uint64_t index = static_cast<uint64_t>(p.sensor_frame[c]);
        p.sensor_checksum_known[c] = m_island->frame_checksum(c, index, &p.sensor_checksum[c]);
        if (const uint8_t* pixels = m_island->frame_pixels(c, index)) {
            uint64_t differing = 0;
            uint8_t bits = 0;
            for (uint32_t i = 0; i < bytes; ++i) {
                const uint8_t x = static_cast<uint8_t>(memory[i] ^ pixels[i]);
                differing += x != 0;
                bits |= x;
            }
            p.differing_pixels[c] = differing;
            p.differing_bits[c] = bits;
        }
    }
}

}  // namespace platform
