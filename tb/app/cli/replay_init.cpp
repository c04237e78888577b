#include "tb/app/cli/replay_init.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "model/scene/png_io.h"
#include "model/scene/replay.h"
#include "tb/app/cli/run_command.h"

namespace cli {

namespace {

namespace fs = std::filesystem;

// A pattern's file of frame `number`, named as a replay will name it.
std::string file_of(const std::string& pattern, int number) {
    std::string name;
    return scene::replay_file_name(pattern, number, &name) ? name : pattern;
}

// The frames of a pattern: the first number (0 or 1) and how many files
// follow it without a gap; {-1, 0} if none.
std::pair<int, int> frames_of(const std::string& pattern) {
    if (pattern.find('%') == std::string::npos)
        return fs::exists(pattern) ? std::pair{0, 1} : std::pair{-1, 0};
    for (int first : {0, 1}) {
        int count = 0;
        while (fs::exists(file_of(pattern, first + count))) ++count;
        if (count > 0) return {first, count};
    }
    return {-1, 0};
}

// A pattern a manifest can hold: one %d or %0Nd (N 1..9) or none, no '#'
// (a manifest comment) and no space at either end (a manifest trims it).
bool pattern_ok(const std::string& pattern) {
    std::string name;
    return scene::replay_file_name(pattern, 0, &name) && pattern.find('#') == std::string::npos &&
           !pattern.empty() && !std::isspace(static_cast<unsigned char>(pattern.front())) &&
           !std::isspace(static_cast<unsigned char>(pattern.back()));
}

bool point_of(const std::string& text, double* x, double* y) {
    char comma = 0, extra = 0;
    return std::sscanf(text.c_str(), "%lf%c%lf%c", x, &comma, y, &extra) == 3 && comma == ',';
}

std::string absolute(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
}

// The manifest's text, or "" and *error.
std::string manifest_text(const replay_init_options& o, std::string* error, std::string* what) {
    const auto bad = [&](const std::string& why) {
        *error = why;
        return std::string();
    };
    if (o.focal_px <= 0) return bad("--focal-px must be > 0 (the focal length in pixels)");
    if (o.baseline_mm <= 0) return bad("--baseline-mm must be > 0 (the cameras' distance)");
    if (!pattern_ok(o.left) || !pattern_ok(o.right))
        return bad(
            "--left / --right: a file, or a pattern with one %d or %0Nd (N 1..9) for "
            "the number, without '#' or a space at either end");
    const std::string left = absolute(o.left), right = absolute(o.right);
    for (const std::string& path : {left, right})
        if (!pattern_ok(path))
            return bad("the path " + path +
                       " has a '%' or '#' outside the pattern: " + "a manifest cannot name it");
    const auto [first, frames] = frames_of(left);
    const auto [first_r, frames_r] = frames_of(right);
    if (frames == 0) return bad("--left: no file " + file_of(left, 0) + " (nor from number 1)");
    if (frames_r == 0) return bad("--right: no file " + file_of(right, 0) + " (nor from number 1)");
    if (first != first_r || frames != frames_r)
        return bad("--left has " + std::to_string(frames) + " frames from number " +
                   std::to_string(first) + ", --right " + std::to_string(frames_r) +
                   " from number " + std::to_string(first_r) + ": one pair per frame");
    scene::png_info info;
    try {
        info = scene::read_image_info(file_of(left, first));
    } catch (const std::exception& e) {
        return bad(e.what());
    }
    double lx = (info.width - 1) / 2.0, ly = (info.height - 1) / 2.0, rx = lx, ry = ly;
    if (!o.principal_left.empty() && !point_of(o.principal_left, &lx, &ly))
        return bad("--principal-left: expected X,Y in pixels, got '" + o.principal_left + "'");
    if (!o.principal_right.empty() && !point_of(o.principal_right, &rx, &ry))
        return bad("--principal-right: expected X,Y in pixels, got '" + o.principal_right + "'");
    const std::string after = !o.after_last.empty() ? o.after_last : frames == 1 ? "hold" : "";
    std::ostringstream m;
    m.precision(10);
    m << "stereosim_replay 1\n# written by stereosim replay init (docs/replay.md)\n"
      << "size " << info.width << " " << info.height << "\nframes " << frames << "\n"
      << "left " << left << "\nright " << right << "\nfirst_number " << first << "\n"
      << "focal_px " << o.focal_px << "\nbaseline_m " << o.baseline_mm / 1000.0 << "\n"
      << "principal_left " << lx << " " << ly << "\nprincipal_right " << rx << " " << ry << "\n";
    if (!after.empty()) m << "after_last " << after << "\n";
    if (!o.truth.empty()) m << "truth " << absolute(o.truth) << "\n";
    char text[256];
    std::snprintf(text, sizeof text, "%d frame(s) of %d x %d", frames, info.width, info.height);
    *what = text;
    return m.str();
}

}  // namespace

bool write_replay_manifest(const replay_init_options& o, std::string* summary, std::string* error) {
    std::string what;
    const std::string text = manifest_text(o, error, &what);
    if (text.empty()) return false;
    std::error_code ec;
    const bool made = !fs::exists(o.dir);
    fs::create_directories(o.dir, ec);
    if (ec) {
        *error = "cannot create " + o.dir + ": " + ec.message();
        return false;
    }
    const std::string staged = o.dir + "/.replay.txt.staged", path = o.dir + "/replay.txt";
    const auto undo = [&] {
        fs::remove(staged, ec);
        if (made) fs::remove(o.dir, ec);
    };
    std::ofstream out(staged);
    out << text;
    out.close();
    if (!out) {
        *error = "cannot write " + staged;
        undo();
        return false;
    }
    // Checked as a run will read it: every file, its format and size, the truth.
    int w = 0, h = 0;
    bool truth = false;
    try {
        const scene::replay checked(staged);
        w = checked.width();
        h = checked.height();
        truth = checked.has_truth();
    } catch (const std::exception& e) {
        std::string why = e.what();
        for (size_t at; (at = why.find(staged)) != std::string::npos;)
            why.replace(at, staged.size(), path);
        *error = why;
        undo();
        return false;
    }
    fs::rename(staged, path, ec);
    if (ec) {
        *error = "cannot write " + path + ": " + ec.message();
        undo();
        return false;
    }
    std::string window;
    if (w != 640 || h != 480)
        window = " --set sensor.window_cols=" + std::to_string(w) +
                 " --set sensor.window_rows=" + std::to_string(h);
    *summary = "written: " + path + " (" + what + (truth ? ", with truth" : "") +
               ")\nrun it:  stereosim run --replay " + absolute(path) + window +
               " --frames 12 --out out/replay";
    return true;
}

replay_command::replay_command(CLI::App& app) {
    m_app = app.add_subcommand("replay", "replays of your own image pairs (docs/replay.md)");
    m_app->require_subcommand(1);
    m_init = m_app->add_subcommand("init", "write and check DIR/replay.txt, a replay manifest");
    replay_init_options& o = m_options;
    m_init->add_option("DIR", o.dir, "folder for replay.txt")->required();
    m_init->add_option("--left", o.left, "left images: a file, or a pattern with %d / %0Nd")
        ->required();
    m_init->add_option("--right", o.right, "right images, the same way")->required();
    m_init->add_option("--focal-px", o.focal_px, "focal length, pixels")->required();
    m_init->add_option("--baseline-mm", o.baseline_mm, "baseline, mm")->required();
    m_init->add_option("--principal-left", o.principal_left,
                       "X,Y: the left principal point, pixels (default the image centre)");
    m_init->add_option("--principal-right", o.principal_right, "X,Y: the right one");
    m_init->add_option("--truth", o.truth, "ground truth CSV (docs/replay.md)");
    m_init
        ->add_option("--after-last", o.after_last,
                     "after the last frame: error | hold | loop (one pair: hold)")
        ->check(CLI::IsMember({"error", "hold", "loop"}));
}

int replay_command::execute() {
    std::string summary, error;
    if (!write_replay_manifest(m_options, &summary, &error)) {
        print_error("replay init: " + error);
        return exit_bad_input;
    }
    std::printf("%s\n", summary.c_str());
    return 0;
}

}  // namespace cli
