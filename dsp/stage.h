// The firmware's processing stages. The names are fixed (docs/design-brief.md,
// "Decisions") and used everywhere: reports, timeline, waveforms.
#pragma once

namespace dsp {

enum class stage : int {
    capture = 0,
    preprocess,
    detect,
    track,
    stereo_sad,
    stereo_edge,
    xyz,
    count_  // number of stages, not a stage
};

constexpr int stage_count = static_cast<int>(stage::count_);

constexpr const char* stage_name(stage s) {
    switch (s) {
        case stage::capture:
            return "capture";
        case stage::preprocess:
            return "preprocess";
        case stage::detect:
            return "detect";
        case stage::track:
            return "track";
        case stage::stereo_sad:
            return "stereo_sad";
        case stage::stereo_edge:
            return "stereo_edge";
        case stage::xyz:
            return "xyz";
        case stage::count_:
            break;
    }
    return "?";
}

}  // namespace dsp
