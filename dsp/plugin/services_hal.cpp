#include "dsp/plugin/services_hal.h"

#include "dsp/controller.h"

namespace dsp::plugin {

namespace {

stereosim_box abi_box(const box& b) {
    return stereosim_box{b.x, b.y, b.width, b.height};
}

}  // namespace

stereosim_kernel_profile abi_profile(const c64x::kernel_profile& kernel) {
    stereosim_kernel_profile p{};
    p.name = kernel.name;
    p.calls = kernel.calls;
    uint32_t sections = 0;
    for (int i = 0; i < kernel.section_count; ++i) {
        const c64x::loop_profile& in = kernel.sections[i];
        // A section entered or run 0 times costs nothing in the model, but
        // the ABI takes 0 entries as 1 (stereosim_section): not passed on.
        if (in.entries == 0 || in.iterations == 0) continue;
        stereosim_section& out = p.sections[sections++];
        out.name = in.name;
        out.ops = {in.ops.l, in.ops.s, in.ops.m, in.ops.d, in.ops.ls, in.ops.lsd};
        out.iterations = in.iterations;
        out.entries = in.entries;
        out.chain = in.chain;
        out.recurrence = in.recurrence;
        out.is_loop = in.is_loop ? 1u : 0u;
    }
    p.section_count = sections;
    p.stream_count = static_cast<uint32_t>(kernel.traffic_count);
    for (int i = 0; i < kernel.traffic_count; ++i) {
        const c64x::memory_traffic& in = kernel.traffic[i];
        p.streams[i] = {in.bytes_read, in.bytes_written, static_cast<uint32_t>(in.where)};
    }
    return p;
}

stereosim_result abi_result(uint32_t pair, const frame_output& out) {
    stereosim_result r{};
    r.pair = pair;
    r.state = static_cast<uint32_t>(out.state);
    r.detected = out.detected ? 1u : 0u;
    r.has_object = out.has_object ? 1u : 0u;
    r.box_left = abi_box(out.box_left);
    r.box_right = abi_box(out.box_right);
    r.has_point = out.has_point ? 1u : 0u;
    r.disparity_q8 = out.disparity_q8;
    r.x_um = out.point.x;
    r.y_um = out.point.y;
    r.z_um = out.point.z;
    for (int s = 0; s < stage_count; ++s) r.stage_cycles[s] = out.stage_cycles[s];
    return r;
}

void services_hal::charge_cycles(stage s, uint64_t cycles) {
    m_s.charge(m_s.ctx, static_cast<uint32_t>(s), cycles, nullptr);
}

void services_hal::charge_with_traffic(stage s, uint64_t cycles, const sdram_traffic& traffic) {
    const stereosim_sdram_traffic t{traffic.bytes_read, traffic.bytes_written};
    m_s.charge(m_s.ctx, static_cast<uint32_t>(s), cycles, &t);
}

uint64_t services_hal::kernel_cycles(const c64x::kernel_profile& kernel) {
    const stereosim_kernel_profile p = abi_profile(kernel);
    return m_s.kernel_cycles(m_s.ctx, &p, nullptr);
}

void services_hal::stage_begin(stage s) {
    m_s.stage_begin(m_s.ctx, static_cast<uint32_t>(s));
}

void services_hal::stage_end(stage s) {
    m_s.stage_end(m_s.ctx, static_cast<uint32_t>(s));
}

uint32_t services_hal::read32(uint32_t address) {
    return m_s.read32(m_s.ctx, address);
}

void services_hal::write32(uint32_t address, uint32_t value) {
    m_s.write32(m_s.ctx, address, value);
}

uint8_t* services_hal::memory(uint32_t address, uint32_t bytes) {
    return m_s.memory(m_s.ctx, address, bytes);
}

void services_hal::set_interrupt_enable(uint32_t ier) {
    m_s.set_interrupt_enable(m_s.ctx, ier);
}

uint32_t services_hal::interrupt_flags() {
    return m_s.interrupt_flags(m_s.ctx);
}

void services_hal::clear_interrupt_flags(uint32_t mask) {
    m_s.clear_interrupt_flags(m_s.ctx, mask);
}

int services_hal::wait_for_interrupt() {
    return m_s.wait_for_interrupt(m_s.ctx);
}

void services_hal::report(const event_record& e) {
    stereosim_event out{static_cast<uint32_t>(e.kind), e.pair, e.value, e.detail, 0, 0};
    if (e.kind == firmware_event::frames_used) {
        out.left = e.value;
        out.right = e.detail;
        out.value = out.detail = 0;
    } else if (e.kind == firmware_event::pair_captured && m_program != nullptr) {
        const int buffer = static_cast<int>(e.detail);
        out.left = m_program->left_address(buffer);
        out.right = m_program->right_address(buffer);
    }
    m_s.report(m_s.ctx, &out);
}

void services_hal::report_result(uint32_t pair, const frame_output& out) {
    stereosim_result r = abi_result(pair, out);
    // The ABI's result holds every cycle charged for the pair: the control
    // program's capture work too, which the controller's output leaves out.
    if (m_program != nullptr)
        r.stage_cycles[static_cast<int>(stage::capture)] += m_program->config().capture_cycles;
    m_s.report_result(m_s.ctx, &r);
}

bool services_hal::stop_requested() {
    return m_s.stop_requested(m_s.ctx) != 0;
}

}  // namespace dsp::plugin
