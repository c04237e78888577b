// Where a sensor's light comes from: one RGB image per camera per frame.
//
// The sensor asks once per frame, at the frame's start (line 0), never per
// pixel. Implementations: model/sensor/scene_sources.h (the scene renderer,
// the PNG replay) and the tests' own deterministic sources.
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "model/scene/camera.h"
#include "model/time/ticks.h"

namespace sensor {

struct frame_request {
    scene::camera_id camera = scene::camera_id::left;
    // Which scene frame: the frame-period time slot the frame starts in,
    // round((frame_start - scene_origin) / frame period) (docs/sensor.md
    // "Scene frames"), so sensors in step ask for the same one whatever their
    // OE restarts. A frame that follows one cut short by OE inside the same
    // period asks for the same scene frame again (with its own timing); an
    // extra frame repeats the previous one without asking.
    uint64_t scene_frame = 0;
    // True timing of this frame on the sensor's own clock: the exposure of the
    // whole frame is taken as [exposure_start, exposure_start + exposure),
    // ending when the first active row is read out (a global-shutter view of
    // the rolling shutter).
    simtime::ticks frame_start = 0;  // rising pclk edge of the frame's first clock
    simtime::ticks exposure_start = 0;
    simtime::ticks exposure = 0;
};

class frame_source {
  public:
    virtual ~frame_source() = default;
    // The scene image for the request, exactly the sensor's active size. The
    // view must stay valid until the next call for the same camera.
    virtual dsp::rgb_cplane frame(const frame_request& request) = 0;
};

}  // namespace sensor
