// The EMIF's TLM-2.0 side in one SystemC simulation holding both
// arrangements side by side, each with its own engine, target and two SRAMs
// (CE2, CE3; card-like timing) and the same initiator scripts (CPU and EDMA
// sockets):
//   fast:      emif_cycle_driver steps engine + C++ SRAMs in one thread;
//   pin-level: emif_pins_sc on sc_signals, the SRAMs in an SC_MODULE, ECLKOUT
//              from a tick clock.
// Checks: b_transport consumes the initiator's delay before the pins move
// and returns exactly at the completion edge (closed form: the first edge
// strictly after the request time + RS + RST + RH, + TA where due); EDMA
// bursts are one b_transport; data and error responses are right; and the
// two arrangements give identical completion times (to the femtosecond),
// data and pin sequences (edge by edge), with the protocol checker silent
// in both.
#include <gtest/gtest.h>

#include <tlm_utils/simple_initiator_socket.h>
#include <chrono>
#include <cstdio>
#include <random>
#include <systemc>
#include <tlm>
#include <vector>

#include "model/emif/emif_checker.h"
#include "model/emif/emif_pins_sc.h"
#include "model/emif/emif_tlm_target_sc.h"
#include "model/sensor/sensor_sc.h"
#include "tests/support/emif/async_sram_slave.h"
#include "tests/support/emif/emif_cycle_driver_sc.h"

using namespace emif;
using sc_core::SC_NS;
using sc_core::sc_time;

namespace {

constexpr uint32_t cectl_card = cectl_dsk_v1;

emif_config bench_config() {
    emif_config c;  // 100 MHz ECLK from tick 0, v1 timing on CE2/CE3, refresh every 1560
    return c;
}

// The slave on each CE space, selected by CE (two SRAMs on one bus).
class two_srams : public emif_pin_slave {
  public:
    two_srams() : m_ce2(sram_config{2, 4096, 2, true}), m_ce3(sram_config{3, 4096, 2, true}) {
        for (uint32_t i = 0; i < 4096; ++i) {
            m_ce2.word(i) = 0x2000000u + i;
            m_ce3.word(i) = 0x3000000u + i * 7;
        }
    }
    emif_inputs outputs(const emif_pins& p) const override {
        if (!p.ce_n[2]) return m_ce2.outputs(p);
        if (!p.ce_n[3]) return m_ce3.outputs(p);
        return emif_inputs{};
    }
    void eclk_edge(const emif_pins& p) override {
        m_ce2.eclk_edge(p);
        m_ce3.eclk_edge(p);
    }

  private:
    async_sram_slave m_ce2, m_ce3;
};

// The SRAMs on sc_signals: flops at ECLKOUT's rising edge, outputs
// recomputed whenever the pins or the flops change.
struct srams_sc : sc_core::sc_module {
    sc_core::sc_in<bool> eclkout;
    sc_core::sc_in<bool> ce0_n, ce1_n, ce2_n, ce3_n, aoe_n, are_n, awe_n, ed_oe;
    sc_core::sc_in<uint32_t> ea, be_n, ed_out;
    sc_core::sc_out<uint32_t> ed_in;
    sc_core::sc_out<bool> ardy;
    two_srams srams;
    sc_core::sc_event flops_changed;

    explicit srams_sc(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          eclkout("eclkout"),
          ce0_n("ce0_n"),
          ce1_n("ce1_n"),
          ce2_n("ce2_n"),
          ce3_n("ce3_n"),
          aoe_n("aoe_n"),
          are_n("are_n"),
          awe_n("awe_n"),
          ed_oe("ed_oe"),
          ea("ea"),
          be_n("be_n"),
          ed_out("ed_out"),
          ed_in("ed_in"),
          ardy("ardy") {
        SC_HAS_PROCESS(srams_sc);
        SC_METHOD(on_edge);
        sensitive << eclkout.pos();
        dont_initialize();
        SC_METHOD(drive);
        sensitive << flops_changed << ce0_n << ce1_n << ce2_n << ce3_n << aoe_n << are_n << awe_n
                  << ed_oe << ea << be_n << ed_out;
        ardy.initialize(true);
    }
    emif_pins pins() const {
        emif_pins p;
        p.ce_n[0] = ce0_n.read();
        p.ce_n[1] = ce1_n.read();
        p.ce_n[2] = ce2_n.read();
        p.ce_n[3] = ce3_n.read();
        p.aoe_n = aoe_n.read();
        p.are_n = are_n.read();
        p.awe_n = awe_n.read();
        p.ed_oe = ed_oe.read();
        p.ea = ea.read();
        p.be_n = static_cast<uint8_t>(be_n.read());
        p.ed_out = ed_out.read();
        return p;
    }
    void on_edge() {
        srams.eclk_edge(pins());
        flops_changed.notify(sc_core::SC_ZERO_TIME);
    }
    void drive() {
        const emif_inputs out = srams.outputs(pins());
        ed_in.write(out.ed_in);
        ardy.write(out.ardy);
    }
};

// Pin changes by edge, and the checker.
struct pin_log : emif_pin_observer {
    struct change {
        uint64_t edge;
        emif_pins pins;
    };
    std::vector<change> changes;  // from the idle pins of reset
    emif_pins last;
    emif_checker checker{bench_config().cectl};
    uint64_t observed = 0;
    void observe(uint64_t edge, const emif_pins& p, const emif_inputs& in) override {
        ++observed;
        if (p != last) changes.push_back({edge, p});
        last = p;
        checker.observe(edge, p, in);
    }
};

struct record {
    int64_t end_fs = 0;
    tlm::tlm_response_status status = tlm::TLM_INCOMPLETE_RESPONSE;
    std::vector<uint8_t> data;
};

// The CPU and EDMA scripts, identical for both arrangements.
struct initiator : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<initiator> cpu, edma;
    std::vector<record> cpu_log, edma_log;

    explicit initiator(sc_core::sc_module_name name)
        : sc_core::sc_module(name), cpu("cpu"), edma("edma") {
        SC_HAS_PROCESS(initiator);
        SC_THREAD(cpu_script);
        SC_THREAD(edma_script);
    }

    record access(tlm_utils::simple_initiator_socket<initiator>& s, bool write, uint64_t address,
                  std::vector<uint8_t> data, sc_time delay, unsigned width = 0,
                  std::vector<uint8_t> byte_enables = {}) {
        tlm::tlm_generic_payload p;
        p.set_command(write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND);
        p.set_address(address);
        p.set_data_ptr(data.data());
        p.set_data_length(static_cast<unsigned>(data.size()));
        p.set_streaming_width(width ? width : static_cast<unsigned>(data.size()));
        if (!byte_enables.empty()) {
            p.set_byte_enable_ptr(byte_enables.data());
            p.set_byte_enable_length(static_cast<unsigned>(byte_enables.size()));
        }
        p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        s->b_transport(p, delay);
        record r;
        r.end_fs = static_cast<int64_t>(sc_core::sc_time_stamp().value());
        r.status = p.get_response_status();
        r.data = data;
        return r;
    }
    static std::vector<uint8_t> word(uint32_t w) {
        return {static_cast<uint8_t>(w), static_cast<uint8_t>(w >> 8),
                static_cast<uint8_t>(w >> 16), static_cast<uint8_t>(w >> 24)};
    }

    void cpu_script() {
        // 1 us of local time, then a write: submitted at 1000 ns = edge 100.
        cpu_log.push_back(access(cpu, true, 0xA0000040, word(0x11223344), sc_time(1000, SC_NS)));
        cpu_log.push_back(access(cpu, false, 0xA0000040, word(0), sc_time(0, SC_NS)));
        cpu_log.push_back(access(cpu, false, 0xB0000008, word(0), sc_time(333, SC_NS)));
        // Byte 2 only.
        cpu_log.push_back(
            access(cpu, true, 0xA0000044, word(0xAABBCCDD), sc_time(5, SC_NS), 0, {0, 0, 0xFF, 0}));
        cpu_log.push_back(access(cpu, false, 0xA0000044, word(0), sc_time(0, SC_NS)));
        // Errors: length 6, outside EMIFA, CE1 at its reset MTYPE (ASYNC8).
        cpu_log.push_back(
            access(cpu, false, 0xA0000000, std::vector<uint8_t>(6), sc_time(0, SC_NS)));
        cpu_log.push_back(access(cpu, false, 0x00001000, word(0), sc_time(0, SC_NS)));
        cpu_log.push_back(access(cpu, false, 0x90000000, word(0), sc_time(0, SC_NS)));
        // Random singles, racing the EDMA bursts (some exactly on edges, some between).
        std::mt19937 rng(7);
        for (int i = 0; i < 60; ++i) {
            const int ce = static_cast<int>(rng() % 3) == 0 ? 0 : 2 + static_cast<int>(rng() % 2);
            const bool write = rng() % 3 == 0;
            const uint64_t address = ce_base(ce) + 4 * (write ? 1024 + rng() % 256 : rng() % 256);
            const sc_time delay = sc_time::from_value(
                (rng() % 4 == 0 ? 1800000ull : 0) * (rng() % 40) + rng() % 300000);
            cpu_log.push_back(access(cpu, write, address, word(rng()), delay));
        }
    }

    void edma_script() {
        wait(sc_time(2000, SC_NS));
        // A burst read of 32 words, incrementing, and one of 24 from a fixed address.
        edma_log.push_back(
            access(edma, false, 0xB0000100, std::vector<uint8_t>(128), sc_time(0, SC_NS)));
        edma_log.push_back(
            access(edma, false, 0xB0000200, std::vector<uint8_t>(96), sc_time(10, SC_NS), 4));
        // 16 words written to CE2 and read back, then 64 words through SDRAM.
        std::vector<uint8_t> block(64);
        for (size_t i = 0; i < block.size(); ++i) block[i] = static_cast<uint8_t>(3 * i + 1);
        edma_log.push_back(access(edma, true, 0xA0000800, block, sc_time(0, SC_NS)));
        edma_log.push_back(
            access(edma, false, 0xA0000800, std::vector<uint8_t>(64), sc_time(0, SC_NS)));
        std::vector<uint8_t> big(256);
        for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(i ^ 0x5A);
        edma_log.push_back(access(edma, true, 0x80002000, big, sc_time(100, SC_NS)));
        edma_log.push_back(
            access(edma, false, 0x80002000, std::vector<uint8_t>(256), sc_time(0, SC_NS)));
        // After a long idle stretch (refreshes due meanwhile): one more burst.
        edma_log.push_back(
            access(edma, false, 0xB0000000, std::vector<uint8_t>(40), sc_time(40000, SC_NS)));
    }
};

struct fast_arrangement : sc_core::sc_module {
    emif_async_master engine;
    two_srams srams;
    pin_log log;
    std::vector<uint8_t> sdram;
    emif_tlm_target target;
    emif_cycle_driver driver;
    initiator init;

    explicit fast_arrangement(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          engine(bench_config()),
          sdram(1 << 16),
          target("target", engine),
          driver("driver", engine, target.work_event(), srams),
          init("init") {
        engine.set_observer(&log);
        engine.set_sdram_storage(sdram.data(), sdram.size());
        init.cpu.bind(target.cpu);
        init.edma.bind(target.edma);
    }
};

struct pin_arrangement : sc_core::sc_module {
    sc_core::sc_signal<bool> eclkout{"eclkout"}, ce0_n{"ce0_n"}, ce1_n{"ce1_n"}, ce2_n{"ce2_n"},
        ce3_n{"ce3_n"}, aoe_n{"aoe_n"}, are_n{"are_n"}, awe_n{"awe_n"}, ed_oe{"ed_oe"},
        ardy{"ardy"};
    sc_core::sc_signal<uint32_t> ea{"ea"}, be_n{"be_n"}, ed_out{"ed_out"}, ed_in{"ed_in"};
    emif_async_master engine;
    pin_log log;
    std::vector<uint8_t> sdram;
    sensor::tick_clock_sc clock;
    emif_tlm_target target;
    emif_pins_sc pins;
    srams_sc srams;
    initiator init;

    explicit pin_arrangement(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          engine(bench_config()),
          sdram(1 << 16),
          clock("clock", bench_config().eclk),
          target("target", engine),
          pins("pins", engine),
          srams("srams"),
          init("init") {
        engine.set_observer(&log);
        engine.set_sdram_storage(sdram.data(), sdram.size());
        clock.clk(eclkout);
        pins.eclkout(eclkout);
        srams.eclkout(eclkout);
        pins.ce0_n(ce0_n), srams.ce0_n(ce0_n);
        pins.ce1_n(ce1_n), srams.ce1_n(ce1_n);
        pins.ce2_n(ce2_n), srams.ce2_n(ce2_n);
        pins.ce3_n(ce3_n), srams.ce3_n(ce3_n);
        pins.aoe_n(aoe_n), srams.aoe_n(aoe_n);
        pins.are_n(are_n), srams.are_n(are_n);
        pins.awe_n(awe_n), srams.awe_n(awe_n);
        pins.ed_oe(ed_oe), srams.ed_oe(ed_oe);
        pins.ea(ea), srams.ea(ea);
        pins.be_n(be_n), srams.be_n(be_n);
        pins.ed_out(ed_out), srams.ed_out(ed_out);
        pins.ed_in(ed_in), srams.ed_in(ed_in);
        pins.ardy(ardy), srams.ardy(ardy);
        init.cpu.bind(target.cpu);
        init.edma.bind(target.edma);
    }
};

int64_t edge_fs(uint64_t edge) {
    return simtime::to_fs(static_cast<simtime::ticks>(edge) * 180);
}

uint32_t word_at(const std::vector<uint8_t>& d, size_t i) {
    return d[4 * i] | d[4 * i + 1] << 8 | d[4 * i + 2] << 16 | uint32_t(d[4 * i + 3]) << 24;
}

}  // namespace

TEST(emif_tlm, fast_and_pin_level_arrangements_agree_to_the_femtosecond) {
    fast_arrangement fast("fast");
    pin_arrangement pin("pin");
    const auto t0 = std::chrono::steady_clock::now();
    sc_core::sc_start(sc_time(200, sc_core::SC_US));
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const auto& c = fast.init.cpu_log;
    const auto& d = fast.init.edma_log;
    ASSERT_EQ(c.size(), 68u);
    ASSERT_EQ(d.size(), 7u);
    // Write submitted at 1000 ns = edge 100: first edge after it 101, + 14 -> edge 115.
    EXPECT_EQ(c[0].status, tlm::TLM_OK_RESPONSE);
    EXPECT_EQ(c[0].end_fs, edge_fs(115));
    // Read back at 1150 ns = edge 115: from 116, TA 2 after the write (edge 117), + 14.
    EXPECT_EQ(c[1].end_fs, edge_fs(131));
    EXPECT_EQ(word_at(c[1].data, 0), 0x11223344u);
    // 333 ns later (1643 ns, between edges 164 and 165): CE3 read from 165, done 179.
    EXPECT_EQ(c[2].end_fs, edge_fs(179));
    EXPECT_EQ(word_at(c[2].data, 0), 0x3000000u + 2 * 7);
    // Byte-enabled write keeps bytes 0, 1, 3 of the SRAM word 0x2000011.
    EXPECT_EQ(word_at(c[4].data, 0), (0x2000011u & ~0x00FF0000u) | 0x00BB0000u);
    EXPECT_EQ(c[5].status, tlm::TLM_BURST_ERROR_RESPONSE);
    EXPECT_EQ(c[6].status, tlm::TLM_ADDRESS_ERROR_RESPONSE);
    EXPECT_EQ(c[7].status, tlm::TLM_COMMAND_ERROR_RESPONSE);
    for (size_t i = 8; i < c.size(); ++i) EXPECT_EQ(c[i].status, tlm::TLM_OK_RESPONSE) << i;
    // EDMA: 32 incrementing words from CE3 word 64, 24 from word 128 (fixed).
    for (size_t i = 0; i < 32; ++i) EXPECT_EQ(word_at(d[0].data, i), 0x3000000u + (64 + i) * 7);
    for (size_t i = 0; i < 24; ++i) EXPECT_EQ(word_at(d[1].data, i), 0x3000000u + 128 * 7);
    for (size_t i = 0; i < 64; ++i) EXPECT_EQ(d[3].data[i], static_cast<uint8_t>(3 * i + 1));
    for (size_t i = 0; i < 256; ++i) EXPECT_EQ(d[5].data[i], static_cast<uint8_t>(i ^ 0x5A));
    for (const auto& r : d) EXPECT_EQ(r.status, tlm::TLM_OK_RESPONSE);
    // The last burst starts after a 40 us idle bus: first edge after the
    // request, + 10 words of 14 (the refresh pattern decides any extra).
    EXPECT_GE(d[6].end_fs - d[5].end_fs, edge_fs(4000 + 140));

    // The two arrangements: identical transactions, times and pins.
    const auto& pc = pin.init.cpu_log;
    const auto& pd = pin.init.edma_log;
    ASSERT_EQ(pc.size(), c.size());
    ASSERT_EQ(pd.size(), d.size());
    for (size_t i = 0; i < c.size(); ++i) {
        EXPECT_EQ(pc[i].end_fs, c[i].end_fs) << "cpu " << i;
        EXPECT_EQ(pc[i].status, c[i].status) << "cpu " << i;
        EXPECT_EQ(pc[i].data, c[i].data) << "cpu " << i;
    }
    for (size_t i = 0; i < d.size(); ++i) {
        EXPECT_EQ(pd[i].end_fs, d[i].end_fs) << "edma " << i;
        EXPECT_EQ(pd[i].data, d[i].data) << "edma " << i;
    }
    const uint64_t last_edge = simtime::tick_clock(bench_config().eclk)
                                   .first_rise_at_or_after(static_cast<simtime::ticks>(
                                       std::max(c.back().end_fs, d.back().end_fs) * 18 / 1000000));
    std::vector<pin_log::change> fc, pcg;
    for (const auto& ch : fast.log.changes)
        if (ch.edge <= last_edge) fc.push_back(ch);
    for (const auto& ch : pin.log.changes)
        if (ch.edge <= last_edge) pcg.push_back(ch);
    for (size_t i = 0; i < std::min(fc.size(), pcg.size()); ++i) {
        if (fc[i].edge != pcg[i].edge || fc[i].pins != pcg[i].pins) {
            ADD_FAILURE() << "first pin difference at change " << i << ": fast edge " << fc[i].edge
                          << " ce " << fc[i].pins.active_ce() << ", pin-level edge " << pcg[i].edge
                          << " ce " << pcg[i].pins.active_ce();
            break;
        }
    }
    ASSERT_EQ(fc.size(), pcg.size());
    size_t mismatches = 0;
    for (size_t i = 0; i < fc.size(); ++i)
        if (fc[i].edge != pcg[i].edge || fc[i].pins != pcg[i].pins) ++mismatches;
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(fc.size(), 400u);
    EXPECT_EQ(fast.log.checker.total(), 0u);
    EXPECT_EQ(pin.log.checker.total(), 0u);
    for (const violation& v : pin.log.checker.violations()) ADD_FAILURE() << to_string(v);
    // Refresh every 1560 edges: the fast engine up to its last access (it
    // sleeps afterwards), the pin-level one over all 200 us (20000 edges).
    EXPECT_EQ(fast.engine.stats().refreshes, last_edge / 1560);
    EXPECT_EQ(pin.engine.stats().refreshes, 20000u / 1560);
    std::printf(
        "%zu transactions, %zu pin changes up to edge %llu identical; fast: %llu edges "
        "stepped, %llu syncs; pin-level: %llu edges; %llu refreshes; wall %.3f s\n",
        c.size() + d.size(), fc.size(), (unsigned long long)last_edge,
        (unsigned long long)fast.log.observed, (unsigned long long)fast.driver.syncs(),
        (unsigned long long)pin.log.observed, (unsigned long long)fast.engine.stats().refreshes,
        wall);
}
