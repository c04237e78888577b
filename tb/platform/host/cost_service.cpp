#include "tb/platform/host/cost_service.h"

#include "dsp/kernel_costs.h"

namespace host {

namespace {

dsp::c64x::kernel_profile model_profile(const stereosim_kernel_profile& kernel) {
    dsp::c64x::kernel_profile k(kernel.name != nullptr ? kernel.name : "");
    k.calls = kernel.calls;
    for (uint32_t i = 0; i < kernel.section_count && i < STEREOSIM_PROFILE_MAX_SECTIONS; ++i) {
        const stereosim_section& in = kernel.sections[i];
        dsp::c64x::loop_profile s;
        s.name = in.name != nullptr ? in.name : "";
        s.ops = {in.ops.l, in.ops.s, in.ops.m, in.ops.d, in.ops.ls, in.ops.lsd};
        s.iterations = in.iterations;
        s.entries = in.entries == 0 ? 1 : in.entries;
        s.chain = in.chain;
        s.recurrence = in.recurrence;
        s.is_loop = in.is_loop != 0;
        k.add(s);
    }
    for (uint32_t i = 0; i < kernel.stream_count && i < STEREOSIM_PROFILE_MAX_STREAMS; ++i) {
        const stereosim_stream& in = kernel.streams[i];
        dsp::c64x::memory_traffic t;
        t.bytes_read = in.bytes_read;
        t.bytes_written = in.bytes_written;
        t.where = in.where == STEREOSIM_IN_SDRAM ? dsp::c64x::placement::sdram
                  : in.where == STEREOSIM_IN_L2  ? dsp::c64x::placement::l2
                                                 : dsp::c64x::placement::l1d;
        k.add(t);
    }
    return k;
}

}  // namespace

uint64_t kernel_cycles(const dsp::c64x::cost_model& model, const stereosim_kernel_profile& kernel,
                       stereosim_sdram_traffic* traffic) {
    const dsp::c64x::kernel_profile k = model_profile(kernel);
    if (traffic != nullptr) {
        const dsp::sdram_traffic t = dsp::cost::sdram_traffic_of(k);
        traffic->bytes_read = t.bytes_read;
        traffic->bytes_written = t.bytes_written;
    }
    return model.cycles(k);
}

}  // namespace host
