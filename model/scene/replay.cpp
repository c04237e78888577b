#include "model/scene/replay.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "model/scene/png_io.h"

namespace scene {

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

// Whole-token number parsing: "12abc" and "" are errors, not 12 and 0.
bool parse_double(const std::string& s, double* out) {
    if (s.empty()) return false;
    char* end = nullptr;
    *out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}

bool parse_int(const std::string& s, int* out) {
    if (s.empty()) return false;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || v < -2147483647L || v > 2147483647L) return false;
    *out = static_cast<int>(v);
    return true;
}

std::vector<std::string> split_ws(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> out;
    for (std::string t; in >> t;) out.push_back(t);
    return out;
}

}  // namespace

std::string replay::name_pattern::format(int number) const {
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < zero_pad)
        digits.insert(0, static_cast<size_t>(zero_pad) - digits.size(), '0');
    return prefix + digits + suffix;
}

namespace {

// A file pattern with exactly one %d or %0Nd (N = 1..9).
template <typename Pattern>
bool parse_pattern(const std::string& text, Pattern* out) {
    const auto pct = text.find('%');
    if (pct == std::string::npos) return false;
    size_t i = pct + 1;
    int width = 0;
    if (i < text.size() && text[i] == '0') {
        ++i;
        if (i >= text.size() || text[i] < '1' || text[i] > '9') return false;
        width = text[i] - '0';
        ++i;
    }
    if (i >= text.size() || text[i] != 'd') return false;
    const std::string suffix = text.substr(i + 1);
    if (suffix.find('%') != std::string::npos) return false;
    out->prefix = text.substr(0, pct);
    out->suffix = suffix;
    out->zero_pad = width;
    return true;
}

}  // namespace

double replay_truth::value(int frame, const std::string& column) const {
    const auto row = rows.find(frame);
    if (row == rows.end())
        throw std::out_of_range("replay truth: no row for frame " + std::to_string(frame));
    for (size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == column) return row->second[i];
    throw std::out_of_range("replay truth: no column '" + column + "'");
}

namespace {

[[noreturn]] void manifest_error(const std::string& path, int line, const std::string& what) {
    throw std::runtime_error("replay manifest " + path +
                             (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + what);
}

}  // namespace

// One "key value..." line of a manifest, with its checks.
struct replay::manifest_line {
    const std::string& path;
    int line_no = 0;
    std::string key, rest;
    std::vector<std::string> args;

    [[noreturn]] void fail(const std::string& what) const { manifest_error(path, line_no, what); }
    void want_args(size_t n) const {
        if (args.size() != n)
            fail("'" + key + "' takes " + std::to_string(n) + " value(s), got " +
                 std::to_string(args.size()));
    }
    double number(size_t i) const {
        double v = 0.0;
        if (!parse_double(args[i], &v)) fail("'" + args[i] + "' is not a number");
        return v;
    }
    int integer(size_t i) const {
        int v = 0;
        if (!parse_int(args[i], &v)) fail("'" + args[i] + "' is not an integer");
        return v;
    }
};

replay::replay(const std::string& manifest_path, int expected_width, int expected_height)
    : m_manifest_path(manifest_path) {
    name_pattern patterns[2];
    std::string truth_path;
    read_manifest(patterns, truth_path);
    if ((expected_width > 0 && expected_width != m_width) ||
        (expected_height > 0 && expected_height != m_height))
        manifest_error(m_manifest_path, 0,
                       "image size " + std::to_string(m_width) + "x" + std::to_string(m_height) +
                           " does not match the sensor's active size " +
                           std::to_string(expected_width) + "x" + std::to_string(expected_height));
    check_frame_files(patterns);
    if (!truth_path.empty()) read_truth(truth_path);
}

void replay::read_manifest(name_pattern (&patterns)[2], std::string& truth_path) {
    std::ifstream in(m_manifest_path);
    if (!in) manifest_error(m_manifest_path, 0, "cannot open");
    std::set<std::string> seen;
    bool have_header = false;
    int line_no = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_no;
        const auto hash = raw.find('#');
        const std::string line = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
        if (line.empty()) continue;
        const auto space = line.find_first_of(" \t");
        manifest_line l{m_manifest_path, line_no};
        l.key = line.substr(0, space);
        l.rest = space == std::string::npos ? std::string() : trim(line.substr(space));
        l.args = split_ws(l.rest);
        if (!have_header) {
            if (l.key != "stereosim_replay" || l.args.size() != 1 || l.args[0] != "1")
                l.fail("the first line must be 'stereosim_replay 1'");
            have_header = true;
            continue;
        }
        if (!seen.insert(l.key).second) l.fail("key '" + l.key + "' given twice");
        apply_key(l, patterns, truth_path);
    }
    if (!have_header) manifest_error(m_manifest_path, 0, "empty (no 'stereosim_replay 1' line)");
    for (const char* key : {"size", "frames", "left", "right", "focal_px", "baseline_m",
                            "principal_left", "principal_right"})
        if (!seen.count(key))
            manifest_error(m_manifest_path, 0, std::string("missing required key '") + key + "'");
}

// A manifest path, resolved against the manifest's folder.
std::string replay::resolve(const std::string& p) const {
    const std::filesystem::path path(p);
    const std::filesystem::path folder = std::filesystem::path(m_manifest_path).parent_path();
    return (path.is_absolute() ? path : folder / path).string();
}

void replay::apply_key(const manifest_line& l, name_pattern (&patterns)[2],
                       std::string& truth_path) {
    const std::string& key = l.key;
    if (key == "size") {
        l.want_args(2);
        m_width = l.integer(0);
        m_height = l.integer(1);
        if (m_width <= 0 || m_height <= 0) l.fail("size must be positive");
    } else if (key == "frames") {
        l.want_args(1);
        m_frames = l.integer(0);
        if (m_frames <= 0) l.fail("frames must be >= 1");
    } else if (key == "left" || key == "right") {
        if (l.rest.empty()) l.fail("'" + key + "' needs a file pattern");
        name_pattern p;
        if (!parse_pattern(l.rest, &p))
            l.fail("file pattern '" + l.rest + "' needs exactly one %d or %0Nd");
        p.prefix = resolve(p.prefix);
        patterns[key == "left" ? 0 : 1] = p;
    } else if (key == "first_number") {
        l.want_args(1);
        m_first_number = l.integer(0);
        if (m_first_number < 0) l.fail("first_number must be >= 0");
    } else if (key == "after_last") {
        l.want_args(1);
        m_after_last = after_last_of(l);
    } else if (key == "truth") {
        if (l.rest.empty()) l.fail("'truth' needs a file");
        truth_path = resolve(l.rest);
    } else {
        apply_calibration_key(l);
    }
}

void replay::apply_calibration_key(const manifest_line& l) {
    const std::string& key = l.key;
    if (key == "focal_px") {
        l.want_args(1);
        m_calibration.focal_px = l.number(0);
        if (!(m_calibration.focal_px > 0.0)) l.fail("focal_px must be > 0");
    } else if (key == "baseline_m") {
        l.want_args(1);
        m_calibration.baseline_m = l.number(0);
        if (!(m_calibration.baseline_m > 0.0)) l.fail("baseline_m must be > 0");
    } else if (key == "principal_left") {
        l.want_args(2);
        m_calibration.cx_left = l.number(0);
        m_calibration.cy_left = l.number(1);
    } else if (key == "principal_right") {
        l.want_args(2);
        m_calibration.cx_right = l.number(0);
        m_calibration.cy_right = l.number(1);
    } else {
        l.fail("unknown key '" + key + "'");
    }
}

replay::after_last_policy replay::after_last_of(const manifest_line& l) {
    if (l.args[0] == "error") return after_last_policy::error;
    if (l.args[0] == "hold") return after_last_policy::hold;
    if (l.args[0] == "loop") return after_last_policy::loop;
    l.fail("after_last must be error, hold or loop");
}

// Every frame file of both sides exists, is a PNG, and has the manifest's size.
void replay::check_frame_files(const name_pattern (&patterns)[2]) {
    for (int side = 0; side < 2; ++side) {
        const std::string side_name = side == 0 ? "left" : "right";
        for (int f = 0; f < m_frames; ++f) {
            const std::string file = patterns[side].format(m_first_number + f);
            const png_info info = [&] {
                try {
                    return read_png_info(file);
                } catch (const std::runtime_error& e) {
                    manifest_error(m_manifest_path, 0,
                                   side_name + " frame " + std::to_string(f) + ": " + e.what());
                }
            }();
            if (info.width != m_width || info.height != m_height)
                manifest_error(m_manifest_path, 0,
                               side_name + " frame " + std::to_string(f) + " '" + file + "' is " +
                                   std::to_string(info.width) + "x" + std::to_string(info.height) +
                                   ", the manifest says " + std::to_string(m_width) + "x" +
                                   std::to_string(m_height));
        }
        m_pattern[side] = patterns[side];
    }
}

void replay::read_truth(const std::string& truth_path) {
    std::ifstream csv(truth_path);
    const auto csv_fail = [&](int line, const std::string& what) -> void {
        throw std::runtime_error("replay truth " + truth_path +
                                 (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                                 what);
    };
    if (!csv) csv_fail(0, "cannot open");
    int csv_line = 0;
    int frame_column = -1;
    for (std::string raw; std::getline(csv, raw);) {
        ++csv_line;
        if (trim(raw).empty()) continue;
        std::vector<std::string> fields;
        std::istringstream row(raw);
        for (std::string f; std::getline(row, f, ',');) fields.push_back(trim(f));
        if (!raw.empty() && raw.back() == ',') fields.push_back({});
        if (m_truth.columns.empty()) {
            for (size_t i = 0; i < fields.size(); ++i) {
                if (fields[i].empty()) csv_fail(csv_line, "empty column name");
                if (fields[i] == "frame") frame_column = static_cast<int>(i);
            }
            if (frame_column < 0) csv_fail(csv_line, "no 'frame' column in the header");
            m_truth.columns = fields;
            continue;
        }
        if (fields.size() != m_truth.columns.size())
            csv_fail(csv_line, std::to_string(fields.size()) + " fields, the header has " +
                                   std::to_string(m_truth.columns.size()));
        std::vector<double> values(fields.size());
        for (size_t i = 0; i < fields.size(); ++i)
            if (!parse_double(fields[i], &values[i]))
                csv_fail(csv_line, "'" + fields[i] + "' is not a number");
        int frame = 0;
        if (!parse_int(fields[frame_column], &frame) || frame < 0 || frame >= m_frames)
            csv_fail(csv_line, "frame '" + fields[frame_column] + "' is not 0.." +
                                   std::to_string(m_frames - 1));
        if (!m_truth.rows.emplace(frame, std::move(values)).second)
            csv_fail(csv_line, "frame " + std::to_string(frame) + " listed twice");
    }
    if (m_truth.columns.empty()) csv_fail(0, "empty (no header)");
}

pinhole_camera replay::camera(camera_id id) const {
    pinhole_camera cam;
    cam.focal_px = m_calibration.focal_px;
    cam.width = m_width;
    cam.height = m_height;
    const bool left = id == camera_id::left;
    cam.cx = left ? m_calibration.cx_left : m_calibration.cx_right;
    cam.cy = left ? m_calibration.cy_left : m_calibration.cy_right;
    cam.centre = left ? vec3{-m_calibration.baseline_m, 0.0, 0.0} : vec3{0.0, 0.0, 0.0};
    return cam;
}

int replay::resolve_index(uint64_t index) const {
    if (index < static_cast<uint64_t>(m_frames)) return static_cast<int>(index);
    switch (m_after_last) {
        case after_last_policy::hold:
            return m_frames - 1;
        case after_last_policy::loop:
            return static_cast<int>(index % static_cast<uint64_t>(m_frames));
        case after_last_policy::error:
            break;
    }
    throw std::out_of_range("replay '" + m_manifest_path + "': frame " + std::to_string(index) +
                            " asked, the sequence has " + std::to_string(m_frames) +
                            " (after_last error)");
}

std::string replay::path(camera_id id, uint64_t index) const {
    const int side = id == camera_id::left ? 0 : 1;
    return m_pattern[side].format(m_first_number + resolve_index(index));
}

const rgb_image& replay::frame(camera_id id, uint64_t index) {
    const int side = id == camera_id::left ? 0 : 1;
    const int i = resolve_index(index);
    if (m_cached_index[side] != i) {
        const std::string file = path(id, index);
        rgb_image img = read_png_rgb(file);
        if (img.width != m_width || img.height != m_height)
            throw std::runtime_error("replay '" + m_manifest_path + "': '" + file + "' is " +
                                     std::to_string(img.width) + "x" + std::to_string(img.height) +
                                     ", the manifest says " + std::to_string(m_width) + "x" +
                                     std::to_string(m_height));
        m_cache[side] = std::move(img);
        m_cached_index[side] = i;
    }
    return m_cache[side];
}

}  // namespace scene
