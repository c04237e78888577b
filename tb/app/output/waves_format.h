// The waveform file formats `stereosim run --waves` writes (docs/waveforms.md).
#pragma once

namespace output {

enum class waves_format { fst, vcd };

inline const char* waves_extension(waves_format f) {
    return f == waves_format::fst ? "fst" : "vcd";
}

}  // namespace output
