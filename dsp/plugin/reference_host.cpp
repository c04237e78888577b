// The reference firmware's optional host entry (include/stereosim/firmware.h,
// stereosim_fw_host): its controller alone over raw pairs the platform hands
// it, charging what the co-simulation charges per pair (the control
// program's capture work and every kernel), for the sweep's closed form.
#include <cstdio>
#include <new>

#include "dsp/controller.h"
#include "dsp/plugin/reference_firmware.h"
#include "dsp/plugin/services_hal.h"

namespace dsp::plugin {

namespace {

struct host_instance {
    explicit host_instance(const stereosim_services& s) : services(s), hal(s) {}
    const stereosim_services& services;
    services_hal hal;
    controller pipeline;
    uint64_t capture_cycles = 0;
    int width = 0, height = 0;
};

void* create(const stereosim_services* services, const stereosim_board* board, const double* values,
             char* error, size_t error_size) {
    if (services == nullptr || board == nullptr || values == nullptr) {
        std::snprintf(error, error_size, "no services, board or key values");
        return nullptr;
    }
    auto* fw = new (std::nothrow) host_instance(*services);
    if (fw == nullptr) {
        std::snprintf(error, error_size, "out of memory");
        return nullptr;
    }
    const control_program_config config = reference_config(*board, values);
    fw->pipeline.init(config.pipeline, fw->hal);
    fw->capture_cycles = config.capture_cycles;
    fw->width = static_cast<int>(board->active_cols);
    fw->height = static_cast<int>(board->active_rows);
    return fw;
}

void process_pair(void* instance, uint32_t pair, const uint8_t* left, const uint8_t* right) {
    auto& fw = *static_cast<host_instance*>(instance);
    // The capture stage as control_program::process_buffer charges it.
    fw.hal.stage_begin(stage::capture);
    fw.hal.charge_cycles(stage::capture, fw.capture_cycles);
    fw.hal.stage_end(stage::capture);
    const gray_cplane l{left, fw.width, fw.height, fw.width};
    const gray_cplane r{right, fw.width, fw.height, fw.width};
    stereosim_result result = abi_result(pair, fw.pipeline.process_pair(l, r));
    result.stage_cycles[static_cast<int>(stage::capture)] += fw.capture_cycles;
    fw.services.report_result(fw.services.ctx, &result);
}

void destroy(void* instance) {
    delete static_cast<host_instance*>(instance);
}

}  // namespace

const stereosim_fw_host& reference_host() {
    static const stereosim_fw_host h{STEREOSIM_FIRMWARE_ABI_VERSION, create, process_pair, destroy};
    return h;
}

}  // namespace dsp::plugin
