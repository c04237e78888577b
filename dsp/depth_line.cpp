#include "dsp/depth_line.h"

#include <cstdint>

namespace dsp {

namespace {

int64_t abs64(int64_t v) {
    return v < 0 ? -v : v;
}

}  // namespace

void depth_line::clear() {
    count = 0;
    last_replaced = false;
}

void depth_line::push(int64_t d) {
    if (count == history) {
        for (int i = 1; i < history; ++i) depth[i - 1] = depth[i];
        --count;
    }
    depth[count++] = d;
}

int32_t depth_line::reported(int32_t measured_um, bool* replaced) {
    *replaced = false;
    if (measured_um <= 0) {
        clear();
        return measured_um;
    }
    const int64_t z = measured_um;
    if (last_replaced) {  // never two in a row: the line starts again here
        clear();
        push(z);
        return measured_um;
    }
    if (count == history) {
        // The three on a line: the middle one within 1/128 of its neighbours'
        // mean (a ball's are, within their noise, 0.1-0.3 % a pair, unless a
        // bounce is among them). A wrong match that drifted (3 %, then 10 %
        // off) is a line of its own: within 1/32 it replaced the good depth
        // after it by 16 %.
        const int64_t middle = (depth[0] + depth[2]) / 2;
        const int64_t next = 2 * depth[2] - depth[1];
        if (128 * abs64(depth[1] - middle) <= middle && next > 0 && next <= INT32_MAX &&
            16 * abs64(z - next) > next) {
            *replaced = true;
            last_replaced = true;
            push(next);
            return static_cast<int32_t>(next);
        }
    }
    push(z);
    return measured_um;
}

}  // namespace dsp
