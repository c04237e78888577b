#include "model/emif/emif_tlm_target_sc.h"

#include "model/time/sc_ticks.h"

namespace emif {

emif_tlm_target::emif_tlm_target(sc_core::sc_module_name name, emif_async_master& engine)
    : sc_core::sc_module(name), cpu("cpu"), edma("edma"), m_engine(engine) {
    if (sc_core::sc_get_time_resolution() != sc_core::sc_time(1, sc_core::SC_FS))
        SC_REPORT_ERROR(this->name(), "the EMIF model needs a 1 fs time resolution");
    cpu.register_b_transport(this, &emif_tlm_target::b_transport_cpu);
    edma.register_b_transport(this, &emif_tlm_target::b_transport_edma);
    m_engine.set_completion_handler(&emif_tlm_target::on_complete, this);
}

void emif_tlm_target::b_transport_cpu(tlm::tlm_generic_payload& p, sc_core::sc_time& delay) {
    transport(requester::cpu, p, delay);
}

void emif_tlm_target::b_transport_edma(tlm::tlm_generic_payload& p, sc_core::sc_time& delay) {
    transport(requester::edma, p, delay);
}

void emif_tlm_target::transport(requester who, tlm::tlm_generic_payload& p,
                                sc_core::sc_time& delay) {
    // Consume the initiator's local time before the pins move.
    wait(delay);
    delay = sc_core::SC_ZERO_TIME;
    p.set_dmi_allowed(false);
    if (p.get_command() == tlm::TLM_IGNORE_COMMAND) {
        p.set_response_status(tlm::TLM_OK_RESPONSE);
        return;
    }
    const unsigned length = p.get_data_length();
    const unsigned width = p.get_streaming_width();
    if (length == 0 || length % 4 != 0 || (width < length && width != 4)) {
        p.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
        return;
    }
    emif_access a;
    a.who = who;
    a.write = p.is_write();
    a.address = static_cast<uint32_t>(p.get_address());
    a.words = length / 4;
    a.increment = width >= length;
    a.data = p.get_data_ptr();
    if (p.get_address() > 0xFFFFFFFFull) {
        p.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    if (const unsigned char* be = p.get_byte_enable_ptr(); be && a.write) {
        const unsigned be_length = p.get_byte_enable_length();
        if (be_length == 0 || be_length % 4 != 0) {
            p.set_response_status(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
            return;
        }
        for (unsigned i = 0; i < be_length; ++i) {
            if (be[i] != be[i % 4]) {  // one pattern for every word: the pins have one BE per word
                p.set_response_status(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
                return;
            }
        }
        a.be_n = 0;
        for (int b = 0; b < 4; ++b)
            if (be[b] != TLM_BYTE_ENABLED) a.be_n |= static_cast<uint8_t>(1u << b);
    }
    sc_core::sc_event done;
    a.user = &done;
    if (!m_engine.submit_at(a, simtime::tick_at_or_before(sc_core::sc_time_stamp()))) {
        p.set_response_status(a.status == access_status::unsupported_memory
                                  ? tlm::TLM_COMMAND_ERROR_RESPONSE
                                  : tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    ++m_transactions;
    m_work.notify(sc_core::SC_ZERO_TIME);
    wait(done);
    p.set_response_status(tlm::TLM_OK_RESPONSE);
}

void emif_tlm_target::on_complete(void* self, emif_access& a) {
    auto* target = static_cast<emif_tlm_target*>(self);
    auto* done = static_cast<sc_core::sc_event*>(a.user);
    if (!done) return;
    const sc_core::sc_time at = simtime::sc_time_of(target->m_engine.edge_tick(a.done_edge));
    const sc_core::sc_time now = sc_core::sc_time_stamp();
    if (at < now)
        SC_REPORT_ERROR(target->name(), "EMIF access completed in the past: the engine ran late");
    done->notify(at > now ? at - now : sc_core::SC_ZERO_TIME);
}

}  // namespace emif
