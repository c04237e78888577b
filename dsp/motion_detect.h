// Detection by three-frame temporal differencing (paper eq. 2-4) and the
// object zone.
//
//   Dif(t-2,t-1) = Binary(|f(t-2) - f(t-1)|)
//   Dif(t-1,t)   = Binary(|f(t-1) - f(t)|)
//   object(t-1)  = Dif(t-2,t-1) AND Dif(t-1,t),  Binary(a) = a > threshold
//
// Masks are 0 / 255 bytes. The object zone: the mask is cleaned (binary
// opening removes specks, closing fills small holes), connected components
// (8-connectivity) are labelled, components smaller than min_area dropped,
// and the largest remaining one is the moving object; its bounding box is
// the reference pattern's zone.
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

// out = |a - b| (bytewise, SUBABS4).
void absdiff(gray_cplane a, gray_cplane b, gray_plane out);
// out = in > threshold ? 255 : 0.
void threshold_binary(gray_cplane in, uint8_t threshold, gray_plane out);
// out = a & b on 0/255 masks.
void mask_and(gray_cplane a, gray_cplane b, gray_plane out);
// Eq. 2-4 fused in one pass: object = (|f0-f1| > th) & (|f1-f2| > th).
void three_frame_difference(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                            uint8_t threshold, gray_plane object_mask);

// Binary 3x3 erosion / dilation of a 0/255 mask; the border outside the
// image counts as background.
void erode_3x3(gray_cplane in, gray_plane out);
void dilate_3x3(gray_cplane in, gray_plane out);

struct component {
    box bbox;
    int area = 0;
};

struct detect_params {
    uint8_t threshold = 20;  // Binary(a) = a > threshold
    int open_passes = 1;     // erosions then dilations (specks)
    int close_passes = 2;    // dilations then erosions (holes)
    int min_area = 30;       // pixels; smaller components are noise
};

struct detection {
    bool found = false;
    box bbox;
    int area = 0;
    int components = 0;  // components at or above min_area
};

// Owns its work buffers, allocated once in init (never in detect).
class motion_detector {
public:
    motion_detector() = default;
    ~motion_detector();
    motion_detector(const motion_detector&) = delete;
    motion_detector& operator=(const motion_detector&) = delete;

    // Size the buffers for images up to max_width x max_height.
    void init(int max_width, int max_height, int max_components = 4096);

    // The moving object at time t-1 from three consecutive gray frames.
    detection detect(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                     const detect_params& params);

    // The cleaned mask of the last detect() call (for tests and waveforms).
    gray_cplane last_mask() const;

    // Statistics of the last call, for the cost model.
    int last_foreground_pixels() const { return m_last_foreground; }

private:
    int m_max_width = 0, m_max_height = 0, m_max_components = 0;
    uint8_t* m_mask = nullptr;
    uint8_t* m_scratch = nullptr;
    int32_t* m_labels = nullptr;
    component* m_components = nullptr;
    int32_t* m_parent = nullptr;
    int m_last_width = 0, m_last_height = 0, m_last_foreground = 0;
};

// Connected components (8-connectivity) of a 0/255 mask; returns how many
// components were written to out (at most max_out, largest first). labels
// and parent are caller workspaces of width*height and max_labels entries.
int connected_components(gray_cplane mask, int32_t* labels, int32_t* parent, int max_labels,
                         component* out, int max_out);

}  // namespace dsp
