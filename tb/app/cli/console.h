// What `stereosim run` shows on a terminal (docs/cli.md): a progress line
// updated in place while the simulation runs (frames done / total, simulated
// ms, simulated/wall speed, ETA), then a summary table from the report
// (verdict, per-stage mean / max against the budget, sync, accuracy,
// simulation speed) and the paths written. Off a terminal the command is
// quiet but for errors.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cli {

class progress_line {
  public:
    progress_line(std::FILE* out, int total_frames, double period_ms);
    // After `done` periods; redraws the line (carriage return, no newline).
    void update(int done);
    // Clears the line.
    void finish();

  private:
    std::FILE* m_out;
    int m_total;
    double m_period_ms;
    std::chrono::steady_clock::time_point m_start;
    size_t m_last_width = 0;
};

// The end-of-run summary of a report (tb/app/cli/run_report.h), the files written
// and the extensions' extra lines.
void print_summary(std::FILE* out, const nlohmann::json& report,
                   const std::vector<std::string>& written,
                   const std::vector<std::string>& extra_lines);

}  // namespace cli
