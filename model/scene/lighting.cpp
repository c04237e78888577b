#include "model/scene/lighting.h"

namespace scene {

lighting lighting::with_step(double t_s, double gain) {
    lighting l;
    l.gain_change = change::step;
    l.change_start_s = t_s;
    l.gain_after = gain;
    return l;
}

lighting lighting::with_ramp(double start_s, double end_s, double gain) {
    lighting l;
    l.gain_change = change::ramp;
    l.change_start_s = start_s;
    l.change_end_s = end_s;
    l.gain_after = gain;
    return l;
}

double lighting::gain_at(double t_s) const {
    switch (gain_change) {
        case change::none:
            return gain_before;
        case change::step:
            return t_s < change_start_s ? gain_before : gain_after;
        case change::ramp: {
            if (t_s <= change_start_s) return gain_before;
            if (t_s >= change_end_s) return gain_after;
            const double a = (t_s - change_start_s) / (change_end_s - change_start_s);
            return gain_before + a * (gain_after - gain_before);
        }
    }
    return gain_before;
}

}  // namespace scene
