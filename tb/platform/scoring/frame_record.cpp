#include "tb/platform/scoring/frame_record.h"

#include <vector>

namespace platform {

int first_motion_frame(const scene::sequence& sequence, int frames) {
    scene::vec3 previous{};
    for (int n = 0; n < frames; ++n) {
        const std::vector<scene::ball_truth> truth = sequence.truth(n);
        if (truth.empty()) return -1;
        const scene::vec3 centre = truth.front().centre_m;
        if (n > 0 && (centre.x != previous.x || centre.y != previous.y || centre.z != previous.z))
            return n;
        previous = centre;
    }
    return -1;
}

}  // namespace platform
