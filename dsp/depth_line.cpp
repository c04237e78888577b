#include "dsp/depth_line.h"

namespace dsp {

namespace {

constexpr int64_t depth_scale = int64_t{1} << 40;  // depth ~ 2^40 / disparity (Q8)

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

int64_t depth_line::reported(int64_t measured_q8, bool* replaced) {
    *replaced = false;
    last_divides = 0;
    if (measured_q8 <= 0) {
        clear();
        return measured_q8;
    }
    last_divides = 1;
    const int64_t z = depth_scale / measured_q8;
    if (last_replaced) {  // never two in a row: the line starts again here
        clear();
        push(z);
        return measured_q8;
    }
    if (count == history) {
        // The three on a line: the middle one within 1/128 of its neighbours'
        // mean (a ball's are, within their noise, 0.1-0.3 % a pair, unless a
        // bounce is among them). A wrong match that drifted (3 %, then 10 %
        // off) is a line of its own: within 1/32 it replaced the good depth
        // after it by 16 %.
        const int64_t middle = (depth[0] + depth[2]) / 2;
        const int64_t next = 2 * depth[2] - depth[1];
        if (128 * abs64(depth[1] - middle) <= middle && next > 0 && 16 * abs64(z - next) > next) {
            *replaced = true;
            last_replaced = true;
            last_divides = 2;
            push(next);
            return depth_scale / next;
        }
    }
    push(z);
    return measured_q8;
}

}  // namespace dsp
