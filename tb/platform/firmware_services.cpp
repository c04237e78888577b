#include "tb/platform/firmware_services.h"

#include <string>

#include "model/c6416/c6416_sc.h"
#include "tb/platform/firmware_crash.h"

namespace platform {

static_assert(STEREOSIM_FW_MAX_STAGES <= c6416::c6416_sc::max_stages,
              "the C6416 model keeps the cycles of every stage a firmware may declare");

namespace {

const firmware_services& services_of(void* ctx) {
    return *static_cast<const firmware_services*>(ctx);
}

probe_hal& probe_of(void* ctx) {
    return services_of(ctx).probe();
}

// The declared stage `s` (the firmware's index; one it did not declare ends the run).
int stage_of(void* ctx, uint32_t s) {
    return static_cast<int>(services_of(ctx).stage(s));
}

void charge(void* ctx, uint32_t s, uint64_t cycles, const stereosim_sdram_traffic* traffic) {
    probe_of(ctx).charge(stage_of(ctx, s), cycles, traffic);
}

uint64_t kernel_cycles(void* ctx, const stereosim_kernel_profile* kernel,
                       stereosim_sdram_traffic* traffic) {
    return probe_of(ctx).kernel_cycles(*kernel, traffic);
}

void report(void* ctx, const stereosim_event* e) {
    probe_of(ctx).report(*e);
}

void report_result(void* ctx, const stereosim_result* r) {
    services_of(ctx).state(r->state);
    probe_of(ctx).report_result(*r);
}

}  // namespace

uint32_t firmware_services::stage(uint32_t s) const {
    if (s >= m_stage_count)
        firmware_broke_abi("stage " + std::to_string(s) + " used, of the " +
                           std::to_string(m_stage_count) + " it declares");
    return s;
}

uint32_t firmware_services::state(uint32_t s) const {
    if (s >= m_state_count)
        firmware_broke_abi("tracker state " + std::to_string(s) + " reported, of the " +
                           std::to_string(m_state_count) + " it declares");
    return s;
}

firmware_services::firmware_services(probe_hal& probe, uint32_t stage_count, uint32_t state_count)
    : m_probe(probe), m_stage_count(stage_count), m_state_count(state_count) {
    stereosim_services& s = m_table;
    s.abi_version = STEREOSIM_FIRMWARE_ABI_VERSION;
    s.ctx = this;
    s.charge = charge;
    s.kernel_cycles = kernel_cycles;
    s.stage_begin = [](void* ctx, uint32_t st) { probe_of(ctx).stage_begin(stage_of(ctx, st)); };
    s.stage_end = [](void* ctx, uint32_t st) { probe_of(ctx).stage_end(stage_of(ctx, st)); };
    s.read32 = [](void* ctx, uint32_t a) { return probe_of(ctx).read32(a); };
    s.write32 = [](void* ctx, uint32_t a, uint32_t v) { probe_of(ctx).write32(a, v); };
    s.memory = [](void* ctx, uint32_t a, uint32_t n) { return probe_of(ctx).memory(a, n); };
    s.set_interrupt_enable = [](void* ctx, uint32_t ier) {
        probe_of(ctx).set_interrupt_enable(ier);
    };
    s.interrupt_flags = [](void* ctx) { return probe_of(ctx).interrupt_flags(); };
    s.clear_interrupt_flags = [](void* ctx, uint32_t m) { probe_of(ctx).clear_interrupt_flags(m); };
    s.wait_for_interrupt = [](void* ctx) -> int32_t { return probe_of(ctx).wait_for_interrupt(); };
    s.stop_requested = [](void* ctx) -> int32_t { return probe_of(ctx).stop_requested() ? 1 : 0; };
    s.report = report;
    s.report_result = report_result;
}

}  // namespace platform
