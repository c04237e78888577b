#include "dsp/preprocess.h"

#include "dsp/gray_convert.h"

namespace dsp {

uint16_t brightness_gain_q8(uint64_t gray_sum, uint32_t pixel_count,
                            const brightness_params& params) {
    if (!params.enabled || pixel_count == 0) return 256;
    if (gray_sum == 0) return params.max_gain_q8;
    // round(256 * target / (sum / count)) without a per-frame float; at most 2^48, fits 64 bits.
    const uint64_t numerator = 256u * uint64_t{params.target_mean} * pixel_count;
    uint64_t gain = (numerator + gray_sum / 2) / gray_sum;
    if (gain < params.min_gain_q8) gain = params.min_gain_q8;
    if (gain > params.max_gain_q8) gain = params.max_gain_q8;
    return static_cast<uint16_t>(gain);
}

void apply_gain(gray_plane image, uint16_t gain_q8) {
    if (gain_q8 == 256 || image.empty()) return;  // identity: (p * 256 + 128) >> 8 == p
    uint8_t lut[256];
    for (uint32_t p = 0; p < 256; ++p) {
        const uint32_t scaled = (p * gain_q8 + 128u) >> 8;
        lut[p] = static_cast<uint8_t>(scaled > 255u ? 255u : scaled);
    }
    for (int y = 0; y < image.height; ++y) {
        uint8_t* row = image.row(y);
        for (int x = 0; x < image.width; ++x) row[x] = lut[row[x]];
    }
}

preprocess_result preprocess_raw_to_gray(gray_cplane raw, cfa_order order,
                                         const brightness_params& params, rgb8* line_scratch,
                                         gray_plane out) {
    preprocess_result result;
    if (raw.empty() || raw.width < 4 || raw.height < 4 || raw.width % 2 != 0 ||
        raw.height % 2 != 0 || out.width != raw.width || out.height != raw.height ||
        line_scratch == nullptr) {
        return result;
    }
    uint64_t gray_sum = 0;
    for (int y = 0; y < raw.height; ++y) {
        demosaic_bilinear_row(raw, order, y, line_scratch);
        uint8_t* gray_row = out.row(y);
        rgb_row_to_gray(line_scratch, raw.width, gray_row);
        uint32_t row_sum = 0;  // at most 255 * width: fits 32 bits for any sensor width
        for (int x = 0; x < raw.width; ++x) row_sum += gray_row[x];
        gray_sum += row_sum;
    }
    const auto pixel_count = static_cast<uint32_t>(raw.width) * static_cast<uint32_t>(raw.height);
    result.mean_before = static_cast<uint32_t>((gray_sum + pixel_count / 2) / pixel_count);
    result.gain_q8 = brightness_gain_q8(gray_sum, pixel_count, params);
    apply_gain(out, result.gain_q8);
    return result;
}

}  // namespace dsp
