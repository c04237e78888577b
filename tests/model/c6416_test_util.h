// Test helpers for the C6416 model's SystemC tests: a TLM memory target for
// the EMIFA sockets with a fixed time per 32-bit word, and a driver for the
// EXT_INT pins.
#pragma once

#include <tlm_utils/simple_target_socket.h>
#include <cstdint>
#include <cstring>
#include <systemc>
#include <tlm>
#include <vector>

#include "model/c6416/c6416_sc.h"
#include "model/time/ticks.h"

namespace c6416_test {

// Stage indices the tests charge to: the chip only counts cycles per index.
namespace stage {
constexpr int capture = 0, preprocess = 1, detect = 2, track = 3;
}

inline sc_core::sc_time fs(int64_t femtoseconds) {
    return sc_core::sc_time::from_value(static_cast<sc_core::sc_time::value_type>(femtoseconds));
}
inline sc_core::sc_time us(double microseconds) {
    return sc_core::sc_time(microseconds, sc_core::SC_US);
}
inline int64_t fs_of(const sc_core::sc_time& t) {
    return static_cast<int64_t>(t.value());
}

// Femtoseconds of CPU edge k of a clock of f_hz, written independently of
// the model: the edge sits on tick floor(k * 18e9 / f_hz), rounded to fs.
inline int64_t cpu_edge_fs(uint64_t k, int64_t f_hz) {
    const __int128 ticks = static_cast<__int128>(k) * 18000000000LL / f_hz;
    return static_cast<int64_t>((ticks * 1000000 * 2 + 18) / 36);
}

struct bus_record {
    sc_core::sc_time start;
    uint64_t address;
    uint32_t length;
    uint32_t streaming_width;
    bool read;
    bool from_edma;
};

// Memory at [base, base + bytes) behind two target sockets (cpu, edma).
// Each 32-bit word costs word_time: annotated onto the delay (loosely
// timed), or, with consume = true, waited inside b_transport after first
// consuming the caller's delay (as the EMIF model does).
class bus_target : public sc_core::sc_module {
  public:
    tlm_utils::simple_target_socket_optional<bus_target> cpu;
    tlm_utils::simple_target_socket_optional<bus_target> edma;

    bus_target(sc_core::sc_module_name name, uint32_t base, uint32_t bytes,
               sc_core::sc_time word_time, bool consume)
        : sc_core::sc_module(name),
          cpu("cpu"),
          edma("edma"),
          m_base(base),
          m_bytes(bytes, 0),
          m_word_time(word_time),
          m_consume(consume) {
        cpu.register_b_transport(this, &bus_target::transport_cpu);
        edma.register_b_transport(this, &bus_target::transport_edma);
    }

    uint8_t* data(uint32_t address) { return &m_bytes[address - m_base]; }
    std::vector<bus_record> records;

  private:
    void transport_cpu(tlm::tlm_generic_payload& t, sc_core::sc_time& delay) {
        transport(t, delay, false);
    }
    void transport_edma(tlm::tlm_generic_payload& t, sc_core::sc_time& delay) {
        transport(t, delay, true);
    }
    void transport(tlm::tlm_generic_payload& t, sc_core::sc_time& delay, bool from_edma) {
        if (m_consume) {
            sc_core::wait(delay);
            delay = sc_core::SC_ZERO_TIME;
        }
        const uint64_t address = t.get_address();
        const uint32_t length = t.get_data_length();
        const uint32_t width = t.get_streaming_width();
        records.push_back(
            {sc_core::sc_time_stamp() + delay, address, length, width, t.is_read(), from_edma});
        if (address < m_base || address + width > m_base + m_bytes.size() || length % 4 != 0) {
            t.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
            return;
        }
        for (uint32_t i = 0; i < length; ++i) {
            uint8_t& cell = m_bytes[address - m_base + (i % width)];
            if (t.is_read()) {
                t.get_data_ptr()[i] = cell;
            } else {
                cell = t.get_data_ptr()[i];
            }
        }
        const sc_core::sc_time cost = m_word_time * static_cast<double>(length / 4);
        if (m_consume) {
            sc_core::wait(cost);
        } else {
            delay += cost;
        }
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }

    uint32_t m_base;
    std::vector<uint8_t> m_bytes;
    sc_core::sc_time m_word_time;
    bool m_consume;
};

// Drives the four EXT_INT pins from a list of (time, pin 4..7, level).
class pin_driver : public sc_core::sc_module {
  public:
    struct change {
        sc_core::sc_time time;
        int pin;
        bool level;
    };
    sc_core::sc_signal<bool> ext_int[4];

    pin_driver(sc_core::sc_module_name name, std::vector<change> changes)
        : sc_core::sc_module(name), m_changes(std::move(changes)) {
        SC_THREAD(run);
    }
    SC_HAS_PROCESS(pin_driver);

    void bind(c6416::c6416_sc& chip) {
        chip.ext_int4(ext_int[0]);
        chip.ext_int5(ext_int[1]);
        chip.ext_int6(ext_int[2]);
        chip.ext_int7(ext_int[3]);
    }

  private:
    void run() {
        for (const change& c : m_changes) {
            if (c.time > sc_core::sc_time_stamp()) sc_core::wait(c.time - sc_core::sc_time_stamp());
            ext_int[c.pin - 4].write(c.level);
        }
    }
    std::vector<change> m_changes;
};

}  // namespace c6416_test
