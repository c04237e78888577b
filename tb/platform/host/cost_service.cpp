#include "tb/platform/host/cost_service.h"

namespace host {

namespace {

c64x::kernel_profile model_profile(const stereosim_kernel_profile& kernel) {
    c64x::kernel_profile k(kernel.name != nullptr ? kernel.name : "");
    k.calls = kernel.calls;
    for (uint32_t i = 0; i < kernel.section_count && i < STEREOSIM_PROFILE_MAX_SECTIONS; ++i) {
        const stereosim_section& in = kernel.sections[i];
        c64x::loop_profile s;
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
        c64x::memory_traffic t;
        t.bytes_read = in.bytes_read;
        t.bytes_written = in.bytes_written;
        t.where = in.where == STEREOSIM_IN_SDRAM ? c64x::placement::sdram
                  : in.where == STEREOSIM_IN_L2  ? c64x::placement::l2
                                                 : c64x::placement::l1d;
        k.add(t);
    }
    return k;
}

}  // namespace

uint64_t kernel_cycles(const c64x::cost_model& model, const stereosim_kernel_profile& kernel,
                       stereosim_sdram_traffic* traffic) {
    const c64x::kernel_profile k = model_profile(kernel);
    if (traffic != nullptr) {
        const c64x::sdram_bytes b = c64x::sdram_bytes_of(k);
        traffic->bytes_read = b.read;
        traffic->bytes_written = b.written;
    }
    return model.cycles(k);
}

}  // namespace host
