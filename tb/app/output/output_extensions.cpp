#include "tb/app/output/output_extensions.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "tb/app/output/fault_markers.h"
#include "tb/app/output/gtkw_writer.h"
#include "tb/app/output/trace_events.h"
#include "tb/app/output/trajectory_plot.h"
#include "tb/app/output/waves_writer.h"

namespace output {

namespace {

using simtime::ticks;

bool write_text(const std::string& path, const std::string& text, std::string* error) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        *error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) {
        *error = "cannot write " + path;
        return false;
    }
    return true;
}

std::string format_ms(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", ms);
    return text;
}

// A file name from the scenario name (letters, digits, - and _).
std::string file_name_of(const std::string& name) {
    std::string s;
    for (char c : name)
        s.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_');
    return s.empty() ? std::string("run") : s;
}

class waveform_output final : public cli::run_extension {
  public:
    void add_options(CLI::App& run) override {
        m_run = &run;
        run.add_option("--waves", m_format_name,
                       "write a waveform of a window of the run, fst or vcd, into DIR/waves/ with "
                       "a GTKWave save file: the card's whole RTL hierarchy and every pin");
        run.add_flag("--vcd", m_vcd_flag, "the same as --waves vcd");
        run.add_option("--waves-from,--vcd-from", m_from_ms,
                       "window start, simulated ms (default 49)");
        run.add_option("--waves-to,--vcd-to", m_to_ms,
                       "window end, simulated ms (default from + 1)");
        run.add_option("--waves-scope,--vcd-scope", m_scope,
                       "pin-trace signals: sensors,card,emif,firmware (default all; the card's "
                       "RTL hierarchy is always written)");
    }

    bool configure(const cli::run_setup& setup, platform::platform_config& config,
                   std::string* error) override {
        if (!parse_format(error)) return false;
        const bool window_given = m_run->count("--waves-from") + m_run->count("--waves-to") > 0;
        if (!m_enabled) {
            if (window_given || m_run->count("--waves-scope") > 0) {
                *error = "--waves-from, --waves-to and --waves-scope need --waves (or --vcd)";
                return false;
            }
            return true;
        }
        if (m_run->count("--out") == 0) {
            *error = "--waves needs --out DIR (the waveform goes to DIR/waves/)";
            return false;
        }
        const double run_ms = static_cast<double>(config.period * config.frames) /
                              (static_cast<double>(simtime::ticks_per_ns) * 1e6);
        // Default: 1 ms from 49 ms (the default scenario's first FRAME_READY is
        // at 49.24 ms), or the run's first ms if it is shorter.
        double from = m_run->count("--waves-from") ? m_from_ms : (run_ms >= 50.0 ? 49.0 : 0.0);
        double to = m_run->count("--waves-to") ? m_to_ms : std::min(from + 1.0, run_ms);
        if (!check_window(from, to, run_ms, error)) return false;
        unsigned groups = platform::trace_all_groups;
        std::string bad;
        if (!m_scope.empty() && !parse_trace_groups(m_scope, &groups, &bad)) {
            *error = "--waves-scope: unknown scope '" + bad + "' (sensors, card, emif, firmware)";
            return false;
        }
        const auto tick_of = [](double ms) {
            return static_cast<ticks>(std::llround(ms * simtime::ticks_per_ns * 1e6));
        };
        m_window = {tick_of(from), tick_of(to)};
        m_name = file_name_of(setup.scenario.name);
        m_waves = std::make_unique<waves_writer>(m_format, m_window, groups);
        config.trace = m_waves.get();
        config.trace_window = m_window;
        return true;
    }

    bool open_outputs(cli::staged_files& files, std::string* error) override {
        if (!m_waves) return true;
        if (!m_waves->open(files.staged_path("waves/" + file_name()))) {
            *error = m_waves->error();
            return false;
        }
        return true;
    }

    bool write(const cli::run_result& run, cli::staged_files& files, std::string* error) override {
        if (!m_waves) return true;
        if (!m_waves->ok() || !m_waves->finished()) {
            *error = m_waves->ok() ? "the waveform was not finished" : m_waves->error();
            return false;
        }
        // Fault onsets are on the timeline only now (the fault extension marks
        // them in add_to_report, after the run finished the file): merge them in.
        std::vector<fault_marker> markers;
        for (const platform::timeline_event& e : run.top.events().events())
            if (e.kind == platform::event_kind::fault)
                markers.push_back({e.tick, static_cast<uint8_t>(1 + e.b)});
        uint64_t added = 0;
        if (!markers.empty() &&
            !add_fault_markers(m_waves->path(), m_format, m_window, markers, &added, error))
            return false;
        // The staged file is renamed into --out DIR after every writer ran.
        m_bytes = file_size(m_waves->path());
        m_gtkw = run.out_dir + "/waves/" + m_name + ".gtkw";
        // The view opens on 10 us of the window (or the whole window): from 2 us
        // before the first fault marker in it, else from its start.
        ticks first = m_window.to;
        for (const fault_marker& m : markers)
            if (m.tick >= m_window.from && m.tick < first) first = m.tick;
        const ticks view =
            first < m_window.to ? std::max<ticks>(m_window.from, first - 2 * 18000) : m_window.from;
        const ticks span = std::min<ticks>(m_window.to - view, 10 * 18000);
        return write_gtkw(
            [&files](const std::string& f) { return files.staged_path("waves/" + f); },
            run.top.firmware_descriptor(), m_name, file_name(), m_waves->signals(), view, span,
            error);
    }

    std::vector<std::string> summary_lines(const cli::run_result& run) override {
        if (!m_waves || run.out_dir.empty()) return {};
        char line[160], size[32];
        if (m_bytes >= 1000000)
            std::snprintf(size, sizeof size, "%.1f MB", static_cast<double>(m_bytes) / 1e6);
        else
            std::snprintf(size, sizeof size, "%.0f kB", static_cast<double>(m_bytes) / 1e3);
        std::snprintf(line, sizeof line, "waveform (%s): %.3f..%.3f ms, %s",
                      waves_extension(m_format), static_cast<double>(m_window.from) / 18e6,
                      static_cast<double>(m_window.to) / 18e6, size);
        return {line, "open it with: gtkwave " + m_gtkw};
    }

  private:
    // --waves fst|vcd, or --vcd.
    bool parse_format(std::string* error) {
        if (m_run->count("--waves") == 0) {
            m_enabled = m_vcd_flag;
            m_format = waves_format::vcd;
            return true;
        }
        if (m_format_name == "fst") {
            m_format = waves_format::fst;
        } else if (m_format_name == "vcd") {
            m_format = waves_format::vcd;
        } else {
            *error = "--waves: unknown format '" + m_format_name + "' (fst, vcd)";
            return false;
        }
        if (m_vcd_flag && m_format != waves_format::vcd) {
            *error = "--vcd is --waves vcd: it cannot go with --waves " + m_format_name;
            return false;
        }
        m_enabled = true;
        return true;
    }

    static bool check_window(double from, double to, double run_ms, std::string* error) {
        const std::string window =
            "--waves window " + format_ms(from) + ".." + format_ms(to) + " ms";
        if (!std::isfinite(from) || !std::isfinite(to) || from < 0 || to < 0) {
            *error = window + ": times must not be negative";
            return false;
        }
        if (from >= to) {
            *error = window + ": --waves-from must be before --waves-to";
            return false;
        }
        if (to > run_ms) {
            *error = window + " is beyond the run (" + format_ms(run_ms) + " ms)";
            return false;
        }
        return true;
    }

    std::string file_name() const { return m_name + "." + waves_extension(m_format); }

    static uint64_t file_size(const std::string& path) {
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (!f) return 0;
        std::fseek(f, 0, SEEK_END);
        const long size = std::ftell(f);
        std::fclose(f);
        return size > 0 ? static_cast<uint64_t>(size) : 0;
    }

    CLI::App* m_run = nullptr;
    std::string m_format_name;
    bool m_vcd_flag = false;
    bool m_enabled = false;
    waves_format m_format = waves_format::vcd;
    double m_from_ms = 0.0, m_to_ms = 0.0;
    std::string m_scope;
    platform::tick_window m_window;
    std::string m_name;
    std::string m_gtkw;
    uint64_t m_bytes = 0;  // the waveform's size as written
    std::unique_ptr<waves_writer> m_waves;
};

class plot_and_trace_output final : public cli::run_extension {
  public:
    void add_options(CLI::App& run) override {
        m_run = &run;
        run.add_flag("--timeline-csv", m_timeline_csv,
                     "also write DIR/timeline.csv: every timeline event, one row each (tick, "
                     "time_ns, kind, name, a, b, c)");
    }

    bool configure(const cli::run_setup& /*setup*/, platform::platform_config& /*config*/,
                   std::string* error) override {
        if (m_timeline_csv && m_run->count("--out") == 0) {
            *error = "--timeline-csv needs --out DIR (it writes DIR/timeline.csv)";
            return false;
        }
        return true;
    }

    bool write(const cli::run_result& run, cli::staged_files& files, std::string* error) override {
        if (!write_text(files.staged_path("timeline.json"), trace_events_json(run.top), error))
            return false;
        if (m_timeline_csv) {
            const std::string path = files.staged_path("timeline.csv");
            if (!run.top.events().write_csv(path)) {
                *error = "cannot write " + path;
                return false;
            }
        }
        const std::string script = files.staged_path("trajectory.gp");
        // frames.csv is staged beside it (the run command writes it first).
        const std::string dir = script.substr(0, script.rfind('/'));
        bool truth = false, estimates = false;
        trajectory_series_present(dir + "/frames.csv", &truth, &estimates);
        if (!write_text(script, trajectory_gnuplot_script(truth || !estimates, estimates), error))
            return false;
        std::string why = "no true or estimated position in frames.csv";
        if ((truth || estimates) && run_gnuplot(dir, &why)) {
            files.staged_path("trajectory.png");
            m_plot_note.clear();
        } else {
            std::remove((dir + "/trajectory.png").c_str());
            m_plot_note = "trajectory.png not drawn: " + why;
        }
        return true;
    }

    std::vector<std::string> summary_lines(const cli::run_result& /*run*/) override {
        if (m_plot_note.empty()) return {};
        return {m_plot_note};
    }

  private:
    CLI::App* m_run = nullptr;
    bool m_timeline_csv = false;
    std::string m_plot_note;
};

}  // namespace

std::unique_ptr<cli::run_extension> make_waveform_output() {
    return std::make_unique<waveform_output>();
}

std::unique_ptr<cli::run_extension> make_plot_and_trace_output() {
    return std::make_unique<plot_and_trace_output>();
}

}  // namespace output
