#include "model/c6416/edma_core.h"

namespace c6416 {

namespace edma = c6416::edma;

namespace {

uint32_t get_half(uint64_t v, bool high) {
    return static_cast<uint32_t>(high ? v >> 32 : v);
}

uint64_t half_bits(uint32_t v, bool high) {
    return high ? static_cast<uint64_t>(v) << 32 : static_cast<uint64_t>(v);
}

int32_t signed16(uint32_t v) {
    return static_cast<int16_t>(static_cast<uint16_t>(v & 0xFFFFu));
}

uint32_t element_bytes_of(uint32_t opt) {
    switch ((opt & edma::opt_esize_mask) >> edma::opt_esize_shift) {
        case edma::esize_16:
            return 2;
        case edma::esize_8:
            return 1;
        default:
            return 4;  // 32-bit (and the reserved code 3)
    }
}

// One side's steps (the header's address update rules).
transfer_side side_of(uint32_t address, uint32_t mode, bool two_d, uint32_t element_bytes,
                      uint32_t elements, int32_t element_index, int32_t frame_index) {
    const int64_t es = element_bytes;
    transfer_side s;
    s.start = address;
    if (two_d) {
        s.element_step = mode == edma::mode_fixed ? 0 : mode == edma::mode_dec ? -es : es;
        s.array_step = mode == edma::mode_fixed ? 0 : frame_index;
    } else {
        switch (mode) {
            case edma::mode_fixed:
                s.element_step = 0;
                break;
            case edma::mode_inc:
                s.element_step = es;
                break;
            case edma::mode_dec:
                s.element_step = -es;
                break;
            default:
                s.element_step = element_index;
                break;
        }
        s.array_step = mode == edma::mode_index
                           ? static_cast<int64_t>(elements - 1) * element_index + frame_index
                           : s.element_step * static_cast<int64_t>(elements);
    }
    return s;
}

}  // namespace

void edma_core::reset() {
    for (uint32_t& w : m_pram) w = 0;
    m_er = m_eer = m_cipr = m_cier = m_ccer = m_epr = 0;
    for (uint32_t& q : m_pqar) q = 0;
    m_requests.clear();
    m_interrupt = false;
    m_submitted = m_completed = m_null_transfers = 0;
}

bool edma_core::read(uint32_t address, uint32_t& value) const {
    if (address >= edma::pram_base && address < edma::pram_base + edma::pram_bytes) {
        value = m_pram[(address - edma::pram_base) / 4];
        return true;
    }
    switch (address) {
        case edma::cipr_l:
            value = get_half(m_cipr, false);
            return true;
        case edma::cipr_h:
            value = get_half(m_cipr, true);
            return true;
        case edma::cier_l:
            value = get_half(m_cier, false);
            return true;
        case edma::cier_h:
            value = get_half(m_cier, true);
            return true;
        case edma::ccer_l:
            value = get_half(m_ccer, false);
            return true;
        case edma::ccer_h:
            value = get_half(m_ccer, true);
            return true;
        case edma::er_l:
            value = get_half(m_er, false);
            return true;
        case edma::er_h:
            value = get_half(m_er, true);
            return true;
        case edma::eer_l:
            value = get_half(m_eer, false);
            return true;
        case edma::eer_h:
            value = get_half(m_eer, true);
            return true;
        case edma::epr_l:
            value = get_half(m_epr, false);
            return true;
        case edma::epr_h:
            value = get_half(m_epr, true);
            return true;
        case edma::ecr_l:
        case edma::ecr_h:
        case edma::esr_l:
        case edma::esr_h:
            value = 0;
            return true;  // write-only
        case edma::pqsr:
            value = 0xFu;
            return true;  // all four queues empty (ASSUMED)
        default:
            break;
    }
    if (address >= edma::pqar0 && address < edma::pqar0 + 16) {
        value = m_pqar[(address - edma::pqar0) / 4];
        return true;
    }
    return false;
}

bool edma_core::write(uint32_t address, uint32_t value) {
    if (address >= edma::pram_base && address < edma::pram_base + edma::pram_bytes) {
        m_pram[(address - edma::pram_base) / 4] = value;
        return true;
    }
    const bool high = address == edma::cipr_h || address == edma::cier_h ||
                      address == edma::ccer_h || address == edma::eer_h || address == edma::ecr_h ||
                      address == edma::esr_h || address == edma::epr_h;
    const uint64_t bits = half_bits(value, high);
    const uint64_t half_mask = half_bits(0xFFFFFFFFu, high);
    switch (address) {
        case edma::cipr_l:
        case edma::cipr_h:
            m_cipr &= ~bits;
            return true;  // write 1 to clear
        case edma::cier_l:
        case edma::cier_h: {
            const uint64_t before = m_cier;
            m_cier = (m_cier & ~half_mask) | bits;
            if ((m_cier & ~before & m_cipr) != 0) m_interrupt = true;
            return true;
        }
        case edma::ccer_l:
        case edma::ccer_h:
            m_ccer = (m_ccer & ~half_mask) | bits;
            return true;
        case edma::eer_l:
        case edma::eer_h: {
            const uint64_t before = m_eer;
            m_eer = (m_eer & ~half_mask) | bits;
            enable_events(m_eer & ~before);
            return true;
        }
        case edma::ecr_l:
        case edma::ecr_h:
            m_er &= ~bits;
            return true;
        case edma::esr_l:
        case edma::esr_h:
            for (int c = 0; c < edma::channels; ++c) {
                if ((bits >> c) & 1u) submit(c);
            }
            return true;
        case edma::epr_l:
        case edma::epr_h:
            m_epr = (m_epr & ~half_mask) | bits;
            return true;
        case edma::er_l:
        case edma::er_h:
        case edma::pqsr:
            return true;  // read-only: ignored
        default:
            break;
    }
    if (address >= edma::pqar0 && address < edma::pqar0 + 16) {
        m_pqar[(address - edma::pqar0) / 4] = value & 0x7u;
        return true;
    }
    return false;
}

void edma_core::event(int channel) {
    if (channel < 0 || channel >= edma::channels) return;
    const uint64_t bit = uint64_t{1} << channel;
    m_er |= bit;
    if (m_eer & bit) {
        m_er &= ~bit;
        submit(channel);
    }
}

void edma_core::enable_events(uint64_t newly_enabled) {
    const uint64_t ready = m_er & newly_enabled;
    for (int c = 0; c < edma::channels; ++c) {
        if ((ready >> c) & 1u) {
            m_er &= ~(uint64_t{1} << c);
            submit(c);
        }
    }
}

void edma_core::submit(int channel) {
    const uint32_t base = (edma::entry(channel) - edma::pram_base) / 4;
    uint32_t* p = &m_pram[base];
    const uint32_t opt = p[0];
    const uint32_t cnt = p[2];
    const uint32_t idx = p[4];
    const uint32_t rld = p[5];
    const uint32_t elements = cnt & 0xFFFFu;
    const uint32_t frames_left = cnt >> 16;  // FRMCNT: arrays / frames after this one
    if (elements == 0) {
        ++m_null_transfers;
        return;
    }
    const uint32_t es = element_bytes_of(opt);
    const bool src_2d = opt & edma::opt_2ds;
    const bool dst_2d = opt & edma::opt_2dd;
    const bool two_d = src_2d || dst_2d;
    const uint32_t sum = (opt & edma::opt_sum_mask) >> edma::opt_sum_shift;
    const uint32_t dum = (opt & edma::opt_dum_mask) >> edma::opt_dum_shift;
    const int32_t element_index = signed16(idx);
    const int32_t frame_index = signed16(idx >> 16);

    transfer_request r;
    r.channel = channel;
    r.opt = opt;
    r.element_bytes = es;
    r.src = side_of(p[1], sum, src_2d, es, elements, element_index, frame_index);
    r.dst = side_of(p[3], dum, dst_2d, es, elements, element_index, frame_index);
    r.sequence = m_submitted++;

    bool last = true;
    if (opt & edma::opt_fs) {
        r.elements = elements;
        r.arrays = frames_left + 1;
    } else if (two_d) {
        // One array per event.
        r.elements = elements;
        r.arrays = 1;
        last = frames_left == 0;
        if (!last) {
            p[1] = static_cast<uint32_t>(p[1] + r.src.array_step);
            p[3] = static_cast<uint32_t>(p[3] + r.dst.array_step);
            p[2] = ((frames_left - 1) << 16) | elements;
        }
    } else {
        // One element per event; a frame ends with its last element.
        r.elements = 1;
        r.arrays = 1;
        const bool frame_end = elements == 1;
        last = frame_end && frames_left == 0;
        if (!last) {
            if (!frame_end) {
                p[1] = static_cast<uint32_t>(p[1] + r.src.element_step);
                p[3] = static_cast<uint32_t>(p[3] + r.dst.element_step);
                p[2] = (frames_left << 16) | (elements - 1);
            } else {
                const int64_t src_step = sum == edma::mode_index ? frame_index : r.src.element_step;
                const int64_t dst_step = dum == edma::mode_index ? frame_index : r.dst.element_step;
                p[1] = static_cast<uint32_t>(p[1] + src_step);
                p[3] = static_cast<uint32_t>(p[3] + dst_step);
                p[2] = ((frames_left - 1) << 16) | (rld >> 16);  // ELECNT from ELERLD
            }
        }
        r.done = frame_end && !last ? completion::intermediate : completion::none;
    }
    if (opt & edma::opt_fs || two_d) r.done = last ? completion::final : completion::intermediate;
    if (last) {
        r.done = completion::final;
        const uint32_t link = rld & 0xFFFFu;
        if ((opt & edma::opt_link) && link + edma::entry_bytes <= edma::pram_bytes) {
            const uint32_t* from = &m_pram[link / 4];
            uint32_t copy[edma::entry_words];
            for (uint32_t i = 0; i < edma::entry_words; ++i) copy[i] = from[i];
            for (uint32_t i = 0; i < edma::entry_words; ++i) p[i] = copy[i];
        } else {
            p[2] = 0;  // no link: the entry is spent
        }
    }
    m_requests.push_back(r);
}

transfer_request edma_core::take_request() {
    transfer_request r = m_requests.front();
    m_requests.pop_front();
    return r;
}

void edma_core::set_completion(uint32_t code) {
    const uint64_t bit = uint64_t{1} << (code & 63u);
    m_cipr |= bit;
    if (m_cier & bit) m_interrupt = true;
    if (m_ccer & bit) submit(static_cast<int>(code & 63u));  // chaining
}

void edma_core::complete(const transfer_request& r) {
    ++m_completed;
    if (r.done == completion::final && (r.opt & edma::opt_tcint)) {
        set_completion(edma::opt_tcc_code(r.opt));
    } else if (r.done == completion::intermediate && (r.opt & edma::opt_atcint)) {
        set_completion((r.opt & edma::opt_atcc_mask) >> edma::opt_atcc_shift);
    }
}

bool edma_core::take_interrupt() {
    const bool raised = m_interrupt;
    m_interrupt = false;
    return raised;
}

}  // namespace c6416
