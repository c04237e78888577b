/* The optional host entry (stereosim/firmware.h, stereosim_fw_host): the
 * vision chain alone over raw pairs the platform hands it, with no card,
 * charging what a co-simulated pair costs (its capture work included), so
 * that `stereosim sweep` prices this firmware in its closed form. */
#include "paper_fw.h"

static void process_pair(void* instance, uint32_t pair, const uint8_t* left, const uint8_t* right) {
    paper_fw* fw = (paper_fw*)instance;
    stereosim_result r;
    /* The capture stage as fw_release charges it. */
    fw->hw->stage_begin(fw->hw->ctx, ST_CAPTURE);
    fw->hw->charge(fw->hw->ctx, ST_CAPTURE, CAPTURE_CYCLES, NULL);
    fw->hw->stage_end(fw->hw->ctx, ST_CAPTURE);
    vision_pair(fw, left, right, &r);
    r.pair = pair;
    r.stage_cycles[ST_CAPTURE] += CAPTURE_CYCLES;
    fw->hw->report_result(fw->hw->ctx, &r);
}

static const stereosim_fw_host host = {STEREOSIM_FIRMWARE_ABI_VERSION, fw_create, process_pair,
                                       fw_destroy};

const stereosim_fw_host* stereosim_firmware_host(void) {
    return &host;
}
