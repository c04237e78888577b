// Human- and machine-readable reports of a host run: the per-frame table
// and the summary the demo prints, and frames.csv.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "tb/host/error_metrics.h"
#include "tb/host/stereo_runner.h"

namespace host {

// One line per frame: frame, state, box, disparity, estimated X Y Z, true
// centre X Y Z, true visible-surface Z (mm), depth error (%).
void print_frame_table(std::FILE* out, const std::vector<frame_record>& records);

// Detection frame, tracked frames, RMSE, modelled cycles per stage in ms.
void print_summary(std::FILE* out, const run_summary& summary, double cpu_hz = 600e6);

// Writes frames.csv (header + one row per frame) to `path` via a temporary
// file in the same directory renamed over it, so a reader never sees a half
// file. false (and *error set) on failure.
bool write_frames_csv(const std::string& path, const std::vector<frame_record>& records,
                      std::string* error);

}  // namespace host
