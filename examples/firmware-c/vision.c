/* The paper's chain at its plainest, on the right camera (the rig's
 * reference frame) with the left one for stereo:
 *   gray      each 2 x 2 Bayer quad's mean, for its four pixels;
 *   detect    three-frame differencing: a pixel moves where the newest frame
 *             differs from both frames before it by more than the threshold;
 *             8 x 8 blocks with a quarter of their pixels moving; the largest
 *             4-connected group of blocks is the object;
 *   track     the object's last look (a template) searched by the sum of
 *             absolute differences within the search radius; lost when the
 *             best match is poor;
 *   stereo    the template searched along its rows in the left image (SAD),
 *             a parabola through the best disparity and its neighbours;
 *   xyz       D = s f / d, X = D x / f, Y = D y / f (right camera frame).
 * Each step's cycles come from the run's cost model for the loop it is. */
#include <stdlib.h>
#include <string.h>

#include "paper_fw.h"

#define BLOCK 8
#define MAX_TEMPLATE 64    /* a side of the tracked box, pixels */
#define LOST_SAD_PER_PX 28 /* mean absolute difference above which the track is lost */
#define MAX_DISPARITY 255

int vision_init(vision* v, uint32_t w, uint32_t h, uint32_t threshold, int32_t search_radius) {
    const size_t px = (size_t)w * h, blocks = (size_t)(w / BLOCK) * (h / BLOCK);
    int i;
    memset(v, 0, sizeof *v);
    v->w = w;
    v->h = h;
    v->threshold = threshold;
    v->search_radius = search_radius;
    for (i = 0; i < 3; ++i) v->gray[i] = (uint8_t*)malloc(px);
    v->left = (uint8_t*)malloc(px);
    v->moving = (uint8_t*)malloc(blocks);
    v->labels = (uint8_t*)malloc(blocks);
    v->queue = (int32_t*)malloc(blocks * sizeof(int32_t));
    v->templ = (uint8_t*)malloc((size_t)MAX_TEMPLATE * MAX_TEMPLATE);
    v->patch = (uint8_t*)malloc((size_t)MAX_TEMPLATE * MAX_TEMPLATE);
    if (!v->gray[0] || !v->gray[1] || !v->gray[2] || !v->left || !v->moving || !v->labels ||
        !v->queue || !v->templ || !v->patch) {
        vision_free(v);
        return 0;
    }
    return 1;
}

void vision_free(vision* v) {
    int i;
    for (i = 0; i < 3; ++i) free(v->gray[i]);
    free(v->left);
    free(v->moving);
    free(v->labels);
    free(v->queue);
    free(v->templ);
    free(v->patch);
    memset(v, 0, sizeof *v);
}

void vision_restart(vision* v) {
    v->frames = 0;
    v->state = TRACKER_DETECT;
}

static stereosim_op_mix ops(uint32_t l, uint32_t s, uint32_t m, uint32_t d, uint32_t lsd) {
    stereosim_op_mix o;
    o.l = l;
    o.s = s;
    o.m = m;
    o.d = d;
    o.ls = 0;
    o.lsd = lsd;
    return o;
}

/* ---- gray ---- */
static void gray_of(const uint8_t* raw, uint8_t* gray, uint32_t w, uint32_t h) {
    uint32_t x, y;
    for (y = 0; y + 1 < h; y += 2) {
        const uint8_t* a = raw + (size_t)y * w;
        const uint8_t* b = a + w;
        uint8_t* ga = gray + (size_t)y * w;
        uint8_t* gb = ga + w;
        for (x = 0; x + 1 < w; x += 2) {
            const uint8_t m = (uint8_t)((a[x] + a[x + 1] + b[x] + b[x + 1] + 2) >> 2);
            ga[x] = ga[x + 1] = gb[x] = gb[x + 1] = m;
        }
    }
}

/* ---- detect ---- */
static uint32_t moving_blocks(vision* v) {
    const uint32_t bw = v->w / BLOCK, bh = v->h / BLOCK;
    uint32_t bx, by, count = 0;
    for (by = 0; by < bh; ++by) {
        for (bx = 0; bx < bw; ++bx) {
            uint32_t x, y, n = 0;
            for (y = by * BLOCK; y < (by + 1) * BLOCK; ++y) {
                const size_t row = (size_t)y * v->w;
                for (x = bx * BLOCK; x < (bx + 1) * BLOCK; ++x) {
                    const int g0 = v->gray[0][row + x];
                    const int d1 = abs(g0 - v->gray[1][row + x]);
                    const int d2 = abs(g0 - v->gray[2][row + x]);
                    n += d1 > (int)v->threshold && d2 > (int)v->threshold;
                }
            }
            v->moving[by * bw + bx] = n >= BLOCK * BLOCK / 4;
            count += v->moving[by * bw + bx];
        }
    }
    return count;
}

/* The largest 4-connected group of moving blocks, as a box in pixels. */
static int largest_group(vision* v, stereosim_box* out) {
    const int32_t bw = (int32_t)(v->w / BLOCK), bh = (int32_t)(v->h / BLOCK);
    int32_t start, best = 0;
    memset(v->labels, 0, (size_t)bw * bh);
    for (start = 0; start < bw * bh; ++start) {
        int32_t head = 0, tail = 0, x0, y0, x1, y1;
        if (!v->moving[start] || v->labels[start]) continue;
        v->labels[start] = 1;
        v->queue[tail++] = start;
        x0 = x1 = start % bw;
        y0 = y1 = start / bw;
        while (head < tail) {
            const int32_t at = v->queue[head++], x = at % bw, y = at / bw;
            const int32_t next[4] = {x > 0 ? at - 1 : -1, x + 1 < bw ? at + 1 : -1,
                                     y > 0 ? at - bw : -1, y + 1 < bh ? at + bw : -1};
            int k;
            x0 = x < x0 ? x : x0;
            x1 = x > x1 ? x : x1;
            y0 = y < y0 ? y : y0;
            y1 = y > y1 ? y : y1;
            for (k = 0; k < 4; ++k) {
                if (next[k] < 0 || !v->moving[next[k]] || v->labels[next[k]]) continue;
                v->labels[next[k]] = 1;
                v->queue[tail++] = next[k];
            }
        }
        if (tail > best) {
            best = tail;
            out->x = x0 * BLOCK;
            out->y = y0 * BLOCK;
            out->w = (x1 - x0 + 1) * BLOCK;
            out->h = (y1 - y0 + 1) * BLOCK;
        }
    }
    return best >= 2;
}

/* The box of the moving pixels inside a group's blocks (one block around). */
static void refine(const vision* v, stereosim_box* b) {
    int32_t x, y, x0 = b->x + b->w, y0 = b->y + b->h, x1 = b->x - 1, y1 = b->y - 1;
    const int32_t xa = b->x > BLOCK ? b->x - BLOCK : 0, ya = b->y > BLOCK ? b->y - BLOCK : 0;
    const int32_t xb = b->x + b->w + BLOCK < (int32_t)v->w ? b->x + b->w + BLOCK : (int32_t)v->w;
    const int32_t yb = b->y + b->h + BLOCK < (int32_t)v->h ? b->y + b->h + BLOCK : (int32_t)v->h;
    for (y = ya; y < yb; ++y) {
        const size_t row = (size_t)y * v->w;
        for (x = xa; x < xb; ++x) {
            const int g0 = v->gray[0][row + x];
            if (abs(g0 - v->gray[1][row + x]) <= (int)v->threshold ||
                abs(g0 - v->gray[2][row + x]) <= (int)v->threshold)
                continue;
            x0 = x < x0 ? x : x0;
            x1 = x > x1 ? x : x1;
            y0 = y < y0 ? y : y0;
            y1 = y > y1 ? y : y1;
        }
    }
    if (x1 < x0 || y1 < y0) return;
    b->x = x0;
    b->y = y0;
    b->w = x1 - x0 + 1;
    b->h = y1 - y0 + 1;
}

static void take_template(vision* v) {
    int32_t y;
    for (y = 0; y < v->box.h; ++y)
        memcpy(v->templ + (size_t)y * v->box.w,
               v->gray[0] + (size_t)(v->box.y + y) * v->w + v->box.x, (size_t)v->box.w);
}

/* The box clipped to the template's largest side, about its centre. */
static void fit_box(stereosim_box* b) {
    if (b->w > MAX_TEMPLATE) {
        b->x += (b->w - MAX_TEMPLATE) / 2;
        b->w = MAX_TEMPLATE;
    }
    if (b->h > MAX_TEMPLATE) {
        b->y += (b->h - MAX_TEMPLATE) / 2;
        b->h = MAX_TEMPLATE;
    }
}

/* ---- SAD ---- */
static uint32_t sad_of(const vision* v, const uint8_t* templ, const uint8_t* image, int32_t x,
                       int32_t y) {
    uint32_t sum = 0;
    int32_t i, j;
    for (j = 0; j < v->box.h; ++j) {
        const uint8_t* a = image + (size_t)(y + j) * v->w + x;
        const uint8_t* t = templ + (size_t)j * v->box.w;
        for (i = 0; i < v->box.w; ++i) sum += (uint32_t)abs(a[i] - t[i]);
    }
    return sum;
}

static uint32_t sad_at(const vision* v, const uint8_t* image, int32_t x, int32_t y) {
    return sad_of(v, v->templ, image, x, y);
}

/* The best SAD position over a grid of `step` around (cx, cy) within r. */
static uint32_t search(const vision* v, int32_t cx, int32_t cy, int32_t r, int32_t step,
                       int32_t* bx, int32_t* by, uint64_t* positions) {
    uint32_t best = 0xFFFFFFFFu;
    int32_t dx, dy;
    for (dy = -r; dy <= r; dy += step) {
        for (dx = -r; dx <= r; dx += step) {
            const int32_t x = cx + dx, y = cy + dy;
            uint32_t s;
            if (x < 0 || y < 0 || x + v->box.w > (int32_t)v->w || y + v->box.h > (int32_t)v->h)
                continue;
            ++*positions;
            s = sad_at(v, v->gray[0], x, y);
            if (s < best) {
                best = s;
                *bx = x;
                *by = y;
            }
        }
    }
    return best;
}

/* Coarse (every second position) then fine (the eight around the best). */
static int track(paper_fw* fw) {
    vision* v = &fw->v;
    int32_t bx = v->box.x, by = v->box.y;
    uint64_t positions = 0;
    uint32_t best;
    search(v, v->box.x, v->box.y, v->search_radius, 2, &bx, &by, &positions);
    best = search(v, bx, by, 1, 1, &bx, &by, &positions);
    fw_charge_loop(fw, ST_TRACK, "sad_track", positions * (uint64_t)(v->box.w * v->box.h),
                   ops(1, 0, 0, 2, 1), 4, positions * (uint64_t)(v->box.w * v->box.h) * 2u, 0,
                   STEREOSIM_IN_L2);
    if (positions == 0 || best > (uint32_t)(LOST_SAD_PER_PX * v->box.w * v->box.h)) return 0;
    /* The template stays the detection's: updating it every frame lets the
     * box drift onto the background a pixel at a time (measured: off by
     * 125 px after 60 frames). A ball that turns or changes size far
     * enough is lost and detected again. */
    v->box.x = bx;
    v->box.y = by;
    return 1;
}

/* The disparity of the box's current look (the right image now) in the left
 * image, Q8, with a parabola through the best whole disparity and its
 * neighbours. */
static int disparity(paper_fw* fw, int32_t* disparity_q8) {
    vision* v = &fw->v;
    int32_t d, y, best_d = -1, dmax = (int32_t)v->w - (v->box.x + v->box.w);
    uint32_t costs[MAX_DISPARITY + 1], best = 0xFFFFFFFFu;
    for (y = 0; y < v->box.h; ++y)
        memcpy(v->patch + (size_t)y * v->box.w,
               v->gray[0] + (size_t)(v->box.y + y) * v->w + v->box.x, (size_t)v->box.w);
    if (dmax > MAX_DISPARITY) dmax = MAX_DISPARITY;
    for (d = 0; d <= dmax; ++d) {
        costs[d] = sad_of(v, v->patch, v->left, v->box.x + d, v->box.y);
        if (costs[d] < best) {
            best = costs[d];
            best_d = d;
        }
    }
    fw_charge_loop(fw, ST_STEREO, "sad_stereo", (uint64_t)(dmax + 1) * v->box.w * v->box.h,
                   ops(1, 0, 0, 2, 1), 4, (uint64_t)(dmax + 1) * v->box.w * v->box.h * 2u, 0,
                   STEREOSIM_IN_L2);
    if (best_d <= 0 || best_d >= dmax) return 0; /* at an end of the range: no minimum */
    {
        const int64_t a = costs[best_d - 1], b = costs[best_d], c = costs[best_d + 1];
        const int64_t den = a - 2 * b + c;
        const int64_t frac_q8 = den > 0 ? (128 * (a - c)) / den : 0;
        *disparity_q8 = best_d * 256 + (int32_t)frac_q8;
    }
    return 1;
}

/* D = s f_px / (d - (cx_left - cx_right)); X = D x / f, Y = D y / f. */
static int point(paper_fw* fw, int32_t disparity_q8, stereosim_result* r) {
    const stereosim_board* b = &fw->board;
    const vision* v = &fw->v;
    const int64_t f_q8 =
        ((int64_t)b->focal_length_um * 1000 * 256 + b->pixel_pitch_nm / 2) / b->pixel_pitch_nm;
    const int64_t den = (int64_t)disparity_q8 - ((int64_t)b->cx_left_q8 - b->cx_right_q8);
    const int64_t x_q8 = (int64_t)v->box.x * 256 + (int64_t)(v->box.w - 1) * 128;
    const int64_t y_q8 = (int64_t)v->box.y * 256 + (int64_t)(v->box.h - 1) * 128;
    fw_charge_loop(fw, ST_XYZ, "xyz", 1, ops(0, 0, 6, 2, 40), 120, 0, 0, STEREOSIM_IN_L1D);
    if (den <= 0) return 0;
    r->z_um = (int32_t)(((int64_t)b->baseline_um * f_q8 + den / 2) / den);
    r->x_um = (int32_t)(((int64_t)b->baseline_um * (x_q8 - b->cx_right_q8)) / den);
    r->y_um = (int32_t)(((int64_t)b->baseline_um * (y_q8 - b->cy_right_q8)) / den);
    return 1;
}

static void stage(paper_fw* fw, uint32_t s, int begin) {
    if (begin)
        fw->hw->stage_begin(fw->hw->ctx, s);
    else
        fw->hw->stage_end(fw->hw->ctx, s);
}

void vision_pair(paper_fw* fw, const uint8_t* raw_left, const uint8_t* raw_right,
                 stereosim_result* r) {
    vision* v = &fw->v;
    uint8_t* oldest = v->gray[2];
    const uint64_t px = (uint64_t)v->w * v->h;
    memset(r, 0, sizeof *r);
    memset(fw->stage_cycles, 0, sizeof fw->stage_cycles);
    stage(fw, ST_GRAY, 1);
    v->gray[2] = v->gray[1];
    v->gray[1] = v->gray[0];
    v->gray[0] = oldest;
    gray_of(raw_right, v->gray[0], v->w, v->h);
    gray_of(raw_left, v->left, v->w, v->h);
    ++v->frames;
    /* The raw frames come from SDRAM through the cache; the gray ones stay in L2. */
    fw_charge_loop(fw, ST_GRAY, "gray", px / 2, ops(0, 1, 0, 8, 4), 8, px * 2, 0,
                   STEREOSIM_IN_SDRAM);
    stage(fw, ST_GRAY, 0);
    if (v->state != TRACKER_TRACK) {
        stereosim_box found;
        stage(fw, ST_DETECT, 1);
        if (v->frames >= 3 && moving_blocks(v) > 0 && largest_group(v, &found)) {
            refine(v, &found);
            fit_box(&found);
            v->box = found;
            take_template(v);
            v->state = TRACKER_TRACK;
            r->detected = 1;
        }
        if (v->frames >= 3)
            fw_charge_loop(fw, ST_DETECT, "three_frame_difference", px, ops(2, 2, 0, 3, 2), 6,
                           px * 3, 0, STEREOSIM_IN_L2);
        stage(fw, ST_DETECT, 0);
    } else {
        stage(fw, ST_TRACK, 1);
        if (!track(fw)) v->state = TRACKER_LOST;
        stage(fw, ST_TRACK, 0);
    }
    if (v->state == TRACKER_TRACK) {
        int32_t d_q8 = 0;
        r->has_object = 1;
        r->box_right = v->box;
        stage(fw, ST_STEREO, 1);
        const int matched = disparity(fw, &d_q8);
        stage(fw, ST_STEREO, 0);
        if (matched) {
            r->box_left = v->box;
            r->box_left.x += (d_q8 + 128) / 256;
            r->disparity_q8 = d_q8;
            stage(fw, ST_XYZ, 1);
            r->has_point = (uint32_t)point(fw, d_q8, r);
            stage(fw, ST_XYZ, 0);
        }
    }
    r->state = v->state;
    memcpy(r->stage_cycles, fw->stage_cycles, sizeof fw->stage_cycles);
}
