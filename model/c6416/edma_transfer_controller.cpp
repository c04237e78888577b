#include "model/c6416/edma_transfer_controller.h"

#include <cstring>

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace regs = c6416;

void edma_transfer_controller::execute(const transfer_request& r) {
    const uint64_t array_bytes = static_cast<uint64_t>(r.elements) * r.element_bytes;
    if (m_staging.size() < array_bytes) m_staging.resize(array_bytes);
    for (uint32_t a = 0; a < r.arrays; ++a) {
        const uint32_t src = static_cast<uint32_t>(r.src.start + r.src.array_step * a);
        const uint32_t dst = static_cast<uint32_t>(r.dst.start + r.dst.array_step * a);
        read_run(src, r.src.element_step, r.elements, r.element_bytes, m_staging.data());
        write_run(dst, r.dst.element_step, r.elements, r.element_bytes, m_staging.data());
    }
}

// One run of `elements` elements of `es` bytes on EMIFA: a whole burst when
// the addresses increment by the element size, a fixed-address stream when
// they do not move (a FIFO port), else one access per element.
void edma_transfer_controller::bus_run(bool write, uint32_t address, int64_t step,
                                       uint32_t elements, uint32_t es, uint8_t* data) {
    const uint32_t length = elements * es;
    if (step == es) {
        m_map.emifa_access(write, address, data, length, length);
    } else if (step == 0) {
        m_map.emifa_access(write, address, data, length, es);
    } else {
        for (uint32_t i = 0; i < elements; ++i) {
            m_map.emifa_access(write, static_cast<uint32_t>(address + step * i), data + i * es, es,
                               es);
        }
    }
}

void edma_transfer_controller::read_run(uint32_t address, int64_t step, uint32_t elements,
                                        uint32_t es, uint8_t* out) {
    if (regs::in_emifa(address) && !m_map.is_local(address)) {
        bus_run(false, address, step, elements, es, out);
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = m_map.memory(a, es)) {
            std::memcpy(out + i * es, p, es);
        } else if (m_map.is_peripheral(a) && es == 4) {
            const uint32_t v = m_map.register_read(a);
            std::memcpy(out + i * es, &v, 4);
        } else {
            m_map.map_error("EDMA read outside the memory map");
            return;
        }
    }
}

void edma_transfer_controller::write_run(uint32_t address, int64_t step, uint32_t elements,
                                         uint32_t es, const uint8_t* in) {
    if (regs::in_emifa(address) && !m_map.is_local(address)) {
        // The bus carries a non-const pointer; a write only reads it.
        bus_run(true, address, step, elements, es, const_cast<uint8_t*>(in));
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = m_map.memory(a, es)) {
            std::memcpy(p, in + i * es, es);
        } else if (m_map.is_peripheral(a) && es == 4) {
            uint32_t v = 0;
            std::memcpy(&v, in + i * es, 4);
            m_map.register_write(a, v);
        } else {
            m_map.map_error("EDMA write outside the memory map");
            return;
        }
    }
}

}  // namespace c6416
