#include "tb/platform/host/firmware_host.h"

#include <utility>

#include "model/scene/bayer_mosaic.h"
#include "tb/platform/host/cost_service.h"

namespace host {

namespace {

firmware_host& host_of(void* ctx) {
    return *static_cast<firmware_host*>(ctx);
}

}  // namespace

firmware_host::firmware_host(const stereosim_fw_host& entry, uint32_t stage_count,
                             scene::scenario scenario, const stereosim_board& board,
                             const c64x::cost_model& model)
    : m_entry(entry),
      m_stage_count(stage_count),
      m_sequence(std::move(scenario)),
      m_board(board),
      m_model(model) {}

std::unique_ptr<firmware_host> firmware_host::create(const stereosim_fw_host& entry,
                                                     uint32_t stage_count, scene::scenario scenario,
                                                     const stereosim_board& board,
                                                     const std::vector<double>& values,
                                                     const c64x::cost_model& model,
                                                     std::string* error) {
    std::unique_ptr<firmware_host> h(
        new firmware_host(entry, stage_count, std::move(scenario), board, model));
    const scene::stereo_rig& rig = h->m_sequence.rig();
    if (static_cast<uint32_t>(rig.width) != board.active_cols ||
        static_cast<uint32_t>(rig.height) != board.active_rows) {
        *error = "the scenario's images are not the sensors' active area";
        return nullptr;
    }
    h->serve();
    char why[256] = "";
    h->m_instance = entry.create(&h->m_services, &h->m_board, values.data(), why, sizeof why);
    if (h->m_instance == nullptr) {
        *error = std::string("the host entry's create refused: ") + (why[0] ? why : "no reason");
        return nullptr;
    }
    return h;
}

firmware_host::~firmware_host() {
    if (m_instance != nullptr) m_entry.destroy(m_instance);
}

// Cycles and results are all a host run reads; the hardware is not there.
void firmware_host::serve() {
    stereosim_services& s = m_services;
    s.abi_version = STEREOSIM_FIRMWARE_ABI_VERSION;
    s.ctx = this;
    s.charge = [](void* ctx, uint32_t stage, uint64_t, const stereosim_sdram_traffic*) {
        firmware_host& h = host_of(ctx);
        if (stage >= h.m_stage_count && h.m_broken.empty())
            h.m_broken = "charged stage " + std::to_string(stage) + ", of the " +
                         std::to_string(h.m_stage_count) + " it declares";
    };
    s.kernel_cycles = [](void* ctx, const stereosim_kernel_profile* k,
                         stereosim_sdram_traffic* traffic) {
        return kernel_cycles(host_of(ctx).m_model, *k, traffic);
    };
    s.stage_begin = [](void*, uint32_t) {};
    s.stage_end = [](void*, uint32_t) {};
    s.read32 = [](void*, uint32_t) { return uint32_t{0}; };
    s.write32 = [](void*, uint32_t, uint32_t) {};
    s.memory = [](void*, uint32_t, uint32_t) -> uint8_t* { return nullptr; };
    s.set_interrupt_enable = [](void*, uint32_t) {};
    s.interrupt_flags = [](void*) { return uint32_t{0}; };
    s.clear_interrupt_flags = [](void*, uint32_t) {};
    s.wait_for_interrupt = [](void*) { return int32_t{STEREOSIM_FW_NO_INTERRUPT}; };
    s.stop_requested = [](void*) { return int32_t{0}; };
    s.report = [](void*, const stereosim_event*) {};
    s.report_result = [](void* ctx, const stereosim_result* r) {
        host_of(ctx).m_results.push_back(*r);
    };
}

bool firmware_host::step(int n, stereosim_result* result, std::string* error) {
    m_sequence.render(n, &m_frame);
    const auto order = static_cast<dsp::cfa_order>(m_board.cfa);
    m_raw_left.resize(m_frame.left.width, m_frame.left.height);
    m_raw_right.resize(m_frame.right.width, m_frame.right.height);
    scene::mosaic(m_frame.left.view(), order, m_raw_left.plane());
    scene::mosaic(m_frame.right.view(), order, m_raw_right.plane());
    m_results.clear();
    m_entry.process_pair(m_instance, static_cast<uint32_t>(n), m_raw_left.view().data,
                         m_raw_right.view().data);
    const std::string pair = "pair " + std::to_string(n) + ": ";
    if (!m_broken.empty()) {
        *error = pair + m_broken;
        return false;
    }
    if (m_results.size() != 1) {
        *error = pair + "the host entry reported " + std::to_string(m_results.size()) +
                 " results, not one";
        return false;
    }
    *result = m_results.front();
    return true;
}

}  // namespace host
