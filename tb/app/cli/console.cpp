#include "tb/app/cli/console.h"

#include <algorithm>
#include <cmath>

#include "tb/app/cli/run_report.h"

namespace cli {

namespace {

using nlohmann::json;

double number_or(const json& v, double fallback) {
    return v.is_number() ? v.get<double>() : fallback;
}

std::string format_seconds(double s) {
    char text[32];
    if (s < 60.0)
        std::snprintf(text, sizeof text, "%.0f s", s);
    else
        std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(s / 60.0),
                      static_cast<int>(std::fmod(s, 60.0)));
    return text;
}

}  // namespace

progress_line::progress_line(std::FILE* out, int total_frames, double period_ms)
    : m_out(out),
      m_total(total_frames),
      m_period_ms(period_ms),
      m_start(std::chrono::steady_clock::now()) {}

void progress_line::update(int done) {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    const double simulated_ms = done * m_period_ms;
    const double speed = wall > 0.0 ? simulated_ms / 1e3 / wall : 0.0;
    const double eta = done > 0 ? wall / done * (m_total - done) : 0.0;
    char text[160];
    const int n =
        std::snprintf(text, sizeof text, "frame %d/%d  %.1f ms simulated  %.4f x real time  ETA %s",
                      done, m_total, simulated_ms, speed, format_seconds(eta).c_str());
    const size_t width = n > 0 ? static_cast<size_t>(n) : 0;
    // Pad over a longer previous line.
    std::fprintf(m_out, "\r%s%*s", text,
                 static_cast<int>(m_last_width > width ? m_last_width - width : 0), "");
    std::fflush(m_out);
    m_last_width = width;
}

void progress_line::finish() {
    std::fprintf(m_out, "\r%*s\r", static_cast<int>(m_last_width), "");
    std::fflush(m_out);
}

namespace {

// The accuracy lines: detection, RMSE, the depth errors.
void print_accuracy(std::FILE* out, const json& accuracy) {
    const json& rmse = accuracy.at("rmse_mm");
    // The same as report.json: a detection without truth of the first motion
    // (a replay without truth) is still a detection.
    const json& detected = accuracy.at("detection_frame");
    std::string latency = !accuracy.at("detect_latency_frames").is_null()
                              ? "detected " + accuracy.at("detect_latency_frames").dump() +
                                    " frame(s) after the first motion"
                          : detected.is_null() ? std::string("no detection")
                                               : "detected at scene frame " + detected.dump() +
                                                     " (no truth of the first motion)";
    std::fprintf(out, "accuracy  %d frames tracked, %s", accuracy.at("frames_tracked").get<int>(),
                 latency.c_str());
    if (rmse.at("x").is_null())
        std::fprintf(out, ", no scored 3D points\n");
    else
        std::fprintf(out, ", RMSE X %.1f Y %.1f Z %.1f mm over %d points\n",
                     number_or(rmse.at("x"), 0), number_or(rmse.at("y"), 0),
                     number_or(rmse.at("z"), 0), accuracy.at("points_scored").get<int>());
    if (!rmse.at("x").is_null()) {
        const json& near = accuracy.at("depth_err_pct_max");
        char in_range[64] = "none in range";
        if (!near.is_null())
            std::snprintf(in_range, sizeof in_range, "max %.2f %% over %d", near.get<double>(),
                          accuracy.at("depth_scored_1_3m").get<int>());
        std::fprintf(out, "          depth error: max %.2f %% over every scored point; 1-3 m: %s\n",
                     number_or(accuracy.at("depth_err_pct_max_all"), 0), in_range);
    }
}

}  // namespace

void print_summary(std::FILE* out, const json& report, const std::vector<std::string>& written,
                   const std::vector<std::string>& extra_lines) {
    const json& config = report.at("config");
    const json& summary = report.at("summary");
    const json& timing = summary.at("timing");
    const json& sync = summary.at("sync");
    const json& accuracy = summary.at("accuracy");
    const json& sim = summary.at("sim");
    const double budget_ms = timing.at("budget_ms").get<double>();
    const int frames = config.at("run").at("frames").get<int>();

    const std::string replay = config.at("scenario").value("replay", std::string());
    const std::string scene =
        replay.empty() ? "scenario " + config.at("scenario").at("name").get<std::string>()
                       : "replay " + replay;
    std::fprintf(
        out,
        "stereosim run: %s, %d frames (%.1f ms), DSK v%d CPU %.0f MHz EMIF %.0f "
        "MHz, %s, seed %lld\n",
        scene.c_str(), frames, frames * budget_ms, config.at("dsk").at("version").get<int>(),
        config.at("dsk").at("cpu_mhz").get<double>(), config.at("dsk").at("eclk_mhz").get<double>(),
        config.at("firmware").at("mode").get<std::string>().c_str(),
        static_cast<long long>(config.at("run").at("seed").get<int64_t>()));
    const bool fits = report.at("verdict") == "within_budget";
    const bool judged = report.at("judged").get<bool>();
    std::fprintf(
        out, "\nVERDICT  %s: %d of %d judged frames over the %.1f ms budget, %zu overruns\n",
        timing.at("judged_periods").get<int>() == 0 ? "NOT JUDGED: no period could be judged"
        : !fits                                     ? "OVER BUDGET"
        : !judged ? "NOT JUDGED, within budget for the stages that ran"
                  : "within budget",
        timing.at("frames_over_budget").get<int>(), timing.at("judged_periods").get<int>(),
        budget_ms, report.at("overruns").size());
    if (report.at("not_judged").is_string())
        std::fprintf(out, "         %s\n", report.at("not_judged").get<std::string>().c_str());
    const json& overruns = report.at("overruns");
    for (size_t i = 0; i < std::min<size_t>(overruns.size(), 3); ++i)
        std::fprintf(out, "         %s\n", overruns[i].at("text").get<std::string>().c_str());
    if (overruns.size() > 3)
        std::fprintf(out, "         ... %zu more in report.json\n", overruns.size() - 3);

    std::fprintf(out, "\n  stage          mean ms    max ms   max / budget\n");
    for (const std::string& stage : stage_names(report)) {
        const json& ms = timing.at("stage_ms").at(stage);
        const double mean = ms.at("mean").get<double>(), max = ms.at("max").get<double>();
        std::fprintf(out, "  %-12s %9.3f %9.3f %9.1f %%\n", stage.c_str(), mean, max,
                     100.0 * max / budget_ms);
    }
    std::fprintf(out,
                 "  capture (bus) %8.3f %9.3f %9.1f %%   (FRAME_READY to the last EDMA burst)\n",
                 timing.at("capture_ms").at("mean").get<double>(),
                 timing.at("capture_ms").at("max").get<double>(),
                 100.0 * timing.at("capture_ms").at("max").get<double>() / budget_ms);
    std::fprintf(
        out,
        "  busy max: CPU %.3f ms, EMIF %.3f ms; FIFO peak L %d R %d words; latency max %.3f ms\n",
        timing.at("cpu_busy_ms_max").get<double>(), timing.at("emif_busy_ms_max").get<double>(),
        timing.at("fifo_peak_words").at("left").get<int>(),
        timing.at("fifo_peak_words").at("right").get<int>(),
        timing.at("latency_ms_max").get<double>());

    std::fprintf(out,
                 "\nsync      %d mismatch(es) detected, %d resync(s), %d unsynced pair(s) used, %d "
                 "pairs forwarded\n",
                 sync.at("mismatches_detected").get<int>(), sync.at("resyncs").get<int>(),
                 sync.at("unsynced_pairs_used").get<int>(), sync.at("pairs_forwarded").get<int>());
    print_accuracy(out, accuracy);
    std::fprintf(out, "sim       %.1f ms simulated in %.2f s wall (%.4f x real time)\n",
                 1e3 * sim.at("simulated_s").get<double>(), sim.at("wall_s").get<double>(),
                 sim.at("ratio").get<double>());
    // The extensions' verdicts (faults) belong to the result, before the files.
    if (!extra_lines.empty()) std::fprintf(out, "\n");
    for (const std::string& line : extra_lines) std::fprintf(out, "%s\n", line.c_str());
    for (size_t i = 0; i < written.size(); ++i)
        std::fprintf(out, "%s%s\n", i == 0 ? "\nwrote     " : "          ", written[i].c_str());
}

}  // namespace cli
