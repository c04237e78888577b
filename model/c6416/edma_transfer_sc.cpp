// The EDMA's transfer controller of c6416_sc (one, ASSUMED): the thread that
// takes the channel controller's (edma_core) transfer requests and moves
// them array by array, through a staging buffer, between L2, the registers
// and EMIFA. Its own file because it is its own hardware block; it needs the
// chip's memory map and EMIFA socket, so it stays a part of the module.
#include <cstring>

#include "dsp/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

namespace c6416 {

namespace regs = dsp::c6416;

void c6416_sc::edma_thread() {
    for (;;) {
        while (!m_edma.has_request()) sc_core::wait(m_edma_kick);
        const transfer_request r = m_edma.take_request();
        const sc_core::sc_time start = sc_core::sc_time_stamp();
        execute(r);
        m_edma_busy += sc_core::sc_time_stamp() - start;
        m_edma_bytes += r.bytes();
        m_edma.complete(r);
        after_edma_change();
    }
}

void c6416_sc::execute(const transfer_request& r) {
    const uint64_t array_bytes = static_cast<uint64_t>(r.elements) * r.element_bytes;
    if (m_staging.size() < array_bytes) m_staging.resize(array_bytes);
    for (uint32_t a = 0; a < r.arrays; ++a) {
        const uint32_t src = static_cast<uint32_t>(r.src.start + r.src.array_step * a);
        const uint32_t dst = static_cast<uint32_t>(r.dst.start + r.dst.array_step * a);
        read_run(src, r.src.element_step, r.elements, r.element_bytes, m_staging.data());
        write_run(dst, r.dst.element_step, r.elements, r.element_bytes, m_staging.data());
    }
}

// One EDMA run of `elements` elements of `es` bytes on EMIFA: a whole burst
// when the addresses increment by the element size, a fixed-address stream
// when they do not move (a FIFO port), else one access per element.
void c6416_sc::bus_run(tlm::tlm_command command, uint32_t address, int64_t step, uint32_t elements,
                       uint32_t es, uint8_t* data) {
    const uint32_t length = elements * es;
    if (step == es) {
        bus_access(emifa_edma, command, address, data, length, length);
    } else if (step == 0) {
        bus_access(emifa_edma, command, address, data, length, es);
    } else {
        for (uint32_t i = 0; i < elements; ++i) {
            bus_access(emifa_edma, command, static_cast<uint32_t>(address + step * i),
                       data + i * es, es, es);
        }
    }
}

void c6416_sc::read_run(uint32_t address, int64_t step, uint32_t elements, uint32_t es,
                        uint8_t* out) {
    if (regs::in_emifa(address) && !m_memory.is_local(address)) {
        bus_run(tlm::TLM_READ_COMMAND, address, step, elements, es, out);
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = memory(a, es)) {
            std::memcpy(out + i * es, p, es);
        } else if (is_peripheral(a) && es == 4) {
            const uint32_t v = register_read(a);
            std::memcpy(out + i * es, &v, 4);
        } else {
            ++m_bus_errors;
            SC_REPORT_WARNING(name(), "EDMA read outside the memory map");
            return;
        }
    }
}

void c6416_sc::write_run(uint32_t address, int64_t step, uint32_t elements, uint32_t es,
                         const uint8_t* in) {
    if (regs::in_emifa(address) && !m_memory.is_local(address)) {
        // TLM payloads carry a non-const pointer; a write only reads it.
        bus_run(tlm::TLM_WRITE_COMMAND, address, step, elements, es, const_cast<uint8_t*>(in));
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = memory(a, es)) {
            std::memcpy(p, in + i * es, es);
        } else if (is_peripheral(a) && es == 4) {
            uint32_t v = 0;
            std::memcpy(&v, in + i * es, 4);
            register_write(a, v);
        } else {
            ++m_bus_errors;
            SC_REPORT_WARNING(name(), "EDMA write outside the memory map");
            return;
        }
    }
}

}  // namespace c6416
