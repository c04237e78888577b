#include "model/scene/replay.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
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
    if (fixed) return prefix;
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < zero_pad)
        digits.insert(0, static_cast<size_t>(zero_pad) - digits.size(), '0');
    return prefix + digits + suffix;
}

namespace {

// A file pattern with exactly one %d or %0Nd (N = 1..9), or none: one file
// for every frame (a pair held).
template <typename Pattern>
bool parse_pattern(const std::string& text, Pattern* out) {
    const auto pct = text.find('%');
    if (pct == std::string::npos) {
        out->prefix = text;
        out->fixed = true;
        return true;
    }
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

bool replay_file_name(const std::string& pattern, int number, std::string* name) {
    replay::name_pattern parsed;
    if (!parse_pattern(pattern, &parsed)) return false;
    *name = parsed.format(number);
    return true;
}

double replay_truth::value(int frame, const std::string& column) const {
    const auto row = rows.find(frame);
    if (row == rows.end())
        throw std::out_of_range("replay truth: no row for frame " + std::to_string(frame));
    for (size_t i = 0; i < columns.size(); ++i)
        if (columns[i] == column) return row->second[i];
    throw std::out_of_range("replay truth: no column '" + column + "'");
}

namespace {

// "<what> <file>[:<line>]: <why>"; line 0: the file as a whole.
[[noreturn]] void throw_at(const char* what, const std::string& file, int line,
                           const std::string& why) {
    throw std::runtime_error(std::string(what) + " " + file +
                             (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + why);
}

[[noreturn]] void manifest_error(const std::string& manifest, int line, const std::string& why) {
    throw_at("replay manifest", manifest, line, why);
}

// A file pattern as parsed, before it becomes the replay's name_pattern.
struct file_pattern {
    std::string prefix, suffix;
    int zero_pad = 0;
    bool fixed = false;
};

// What the manifest says, before the image files are checked.
struct manifest_values {
    int width = 0, height = 0, frames = 0, first_number = 0;
    replay_calibration calibration;
    replay::after_last_policy after_last = replay::after_last_policy::error;
    file_pattern patterns[2];  // [camera_id], prefix resolved
    std::string truth_path;    // resolved; "" = none
};

// One "key values..." line of the manifest, with the checks of its values.
struct manifest_line {
    const std::string& manifest;
    int line_no;
    std::string key, rest;
    std::vector<std::string> args;

    [[noreturn]] void fail(const std::string& why) const { manifest_error(manifest, line_no, why); }
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

// A path relative to the manifest's folder (or absolute).
std::string resolve(const std::filesystem::path& folder, const std::string& p) {
    const std::filesystem::path path(p);
    return (path.is_absolute() ? path : folder / path).string();
}

// The calibration keys; false if `l` is not one.
bool apply_calibration_key(const manifest_line& l, replay_calibration* c) {
    if (l.key == "focal_px") {
        l.want_args(1);
        c->focal_px = l.number(0);
        if (!(c->focal_px > 0.0)) l.fail("focal_px must be > 0");
    } else if (l.key == "baseline_m") {
        l.want_args(1);
        c->baseline_m = l.number(0);
        if (!(c->baseline_m > 0.0)) l.fail("baseline_m must be > 0");
    } else if (l.key == "principal_left") {
        l.want_args(2);
        c->cx_left = l.number(0);
        c->cy_left = l.number(1);
    } else if (l.key == "principal_right") {
        l.want_args(2);
        c->cx_right = l.number(0);
        c->cy_right = l.number(1);
    } else {
        return false;
    }
    return true;
}

replay::after_last_policy after_last_of(const manifest_line& l) {
    l.want_args(1);
    if (l.args[0] == "error") return replay::after_last_policy::error;
    if (l.args[0] == "hold") return replay::after_last_policy::hold;
    if (l.args[0] == "loop") return replay::after_last_policy::loop;
    l.fail("after_last must be error, hold or loop");
}

void apply_key(const manifest_line& l, const std::filesystem::path& folder, manifest_values* m) {
    if (l.key == "size") {
        l.want_args(2);
        m->width = l.integer(0);
        m->height = l.integer(1);
        if (m->width <= 0 || m->height <= 0) l.fail("size must be positive");
    } else if (l.key == "frames") {
        l.want_args(1);
        m->frames = l.integer(0);
        if (m->frames <= 0) l.fail("frames must be >= 1");
    } else if (l.key == "left" || l.key == "right") {
        if (l.rest.empty()) l.fail("'" + l.key + "' needs a file pattern");
        file_pattern p;
        if (!parse_pattern(l.rest, &p))
            l.fail("file pattern '" + l.rest +
                   "' has more than one %d, or a % that is no %d or %0Nd");
        p.prefix = resolve(folder, p.prefix);
        m->patterns[l.key == "left" ? 0 : 1] = p;
    } else if (l.key == "first_number") {
        l.want_args(1);
        m->first_number = l.integer(0);
        if (m->first_number < 0) l.fail("first_number must be >= 0");
    } else if (l.key == "after_last") {
        m->after_last = after_last_of(l);
    } else if (l.key == "truth") {
        if (l.rest.empty()) l.fail("'truth' needs a file");
        m->truth_path = resolve(folder, l.rest);
    } else if (!apply_calibration_key(l, &m->calibration)) {
        l.fail("unknown key '" + l.key + "'");
    }
}

manifest_line split_line(const std::string& manifest, int line_no, const std::string& line) {
    const auto space = line.find_first_of(" \t");
    manifest_line l{manifest, line_no, line.substr(0, space), {}, {}};
    l.rest = space == std::string::npos ? std::string() : trim(line.substr(space));
    l.args = split_ws(l.rest);
    return l;
}

manifest_values read_manifest(const std::string& manifest) {
    std::ifstream in(manifest);
    if (!in) manifest_error(manifest, 0, "cannot open");
    const std::filesystem::path folder = std::filesystem::path(manifest).parent_path();
    manifest_values m;
    std::set<std::string> seen;
    bool have_header = false;
    int line_no = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++line_no;
        const auto hash = raw.find('#');
        const std::string line = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
        if (line.empty()) continue;
        const manifest_line l = split_line(manifest, line_no, line);
        if (!have_header) {
            if (l.key != "stereosim_replay" || l.args.size() != 1 || l.args[0] != "1")
                l.fail("the first line must be 'stereosim_replay 1'");
            have_header = true;
            continue;
        }
        if (!seen.insert(l.key).second) l.fail("key '" + l.key + "' given twice");
        apply_key(l, folder, &m);
    }
    if (!have_header) manifest_error(manifest, 0, "empty (no 'stereosim_replay 1' line)");
    for (const char* key : {"size", "frames", "left", "right", "focal_px", "baseline_m",
                            "principal_left", "principal_right"})
        if (!seen.count(key))
            manifest_error(manifest, 0, std::string("missing required key '") + key + "'");
    return m;
}

// Every frame file of one camera exists and has the manifest's size.
void check_frame_files(const std::string& manifest, const manifest_values& m, int side,
                       const std::function<std::string(int frame)>& file_of) {
    const std::string side_name = side == 0 ? "left" : "right";
    for (int f = 0; f < m.frames; ++f) {
        const std::string file = file_of(f);
        const png_info info = [&] {
            try {
                return read_image_info(file);
            } catch (const std::runtime_error& e) {
                manifest_error(manifest, 0,
                               side_name + " frame " + std::to_string(f) + ": " + e.what());
            }
        }();
        if (info.width != m.width || info.height != m.height)
            manifest_error(manifest, 0,
                           side_name + " frame " + std::to_string(f) + " '" + file + "' is " +
                               std::to_string(info.width) + "x" + std::to_string(info.height) +
                               ", the manifest says " + std::to_string(m.width) + "x" +
                               std::to_string(m.height));
    }
}

// The fields of one CSV line, trimmed; a trailing comma ends with an empty one.
std::vector<std::string> csv_fields(const std::string& raw) {
    std::vector<std::string> fields;
    std::istringstream row(raw);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(trim(f));
    if (!raw.empty() && raw.back() == ',') fields.push_back({});
    return fields;
}

// The header's index of the "frame" column.
int frame_column_of(const std::vector<std::string>& header, const std::string& file, int line) {
    int frame_column = -1;
    for (size_t i = 0; i < header.size(); ++i) {
        if (header[i].empty()) throw_at("replay truth", file, line, "empty column name");
        if (header[i] == "frame") frame_column = static_cast<int>(i);
    }
    if (frame_column < 0) throw_at("replay truth", file, line, "no 'frame' column in the header");
    return frame_column;
}

void add_truth_row(const std::vector<std::string>& fields, int frame_column, int frames,
                   const std::string& file, int line, replay_truth* truth) {
    const auto fail = [&](const std::string& why) { throw_at("replay truth", file, line, why); };
    if (fields.size() != truth->columns.size())
        fail(std::to_string(fields.size()) + " fields, the header has " +
             std::to_string(truth->columns.size()));
    std::vector<double> values(fields.size());
    for (size_t i = 0; i < fields.size(); ++i)
        if (!parse_double(fields[i], &values[i])) fail("'" + fields[i] + "' is not a number");
    int frame = 0;
    if (!parse_int(fields[frame_column], &frame) || frame < 0 || frame >= frames)
        fail("frame '" + fields[frame_column] + "' is not 0.." + std::to_string(frames - 1));
    if (!truth->rows.emplace(frame, std::move(values)).second)
        fail("frame " + std::to_string(frame) + " listed twice");
}

// x/y/z and u/v come in groups: a group half given is a malformed file.
void check_object_columns(const std::string& file, const replay_truth& truth) {
    const auto count = [&](std::initializer_list<const char*> group) {
        int n = 0;
        for (const char* name : group)
            for (const std::string& c : truth.columns) n += c == name;
        return n;
    };
    const int xyz = count({"x_mm", "y_mm", "z_mm"});
    const int uv = count({"u_right_px", "v_right_px"});
    if (xyz != 0 && xyz != 3)
        throw_at("replay truth", file, 1, "x_mm, y_mm and z_mm come together");
    if (uv != 0 && uv != 2)
        throw_at("replay truth", file, 1, "u_right_px and v_right_px come together");
    if (count({"z_visible_mm"}) && xyz == 0)
        throw_at("replay truth", file, 1, "z_visible_mm needs x_mm, y_mm and z_mm");
}

replay_truth read_truth_csv(const std::string& file, int frames) {
    std::ifstream csv(file);
    if (!csv) throw_at("replay truth", file, 0, "cannot open");
    replay_truth truth;
    int line = 0;
    int frame_column = -1;
    for (std::string raw; std::getline(csv, raw);) {
        ++line;
        if (trim(raw).empty()) continue;
        std::vector<std::string> fields = csv_fields(raw);
        if (truth.columns.empty()) {
            frame_column = frame_column_of(fields, file, line);
            truth.columns = std::move(fields);
            continue;
        }
        add_truth_row(fields, frame_column, frames, file, line, &truth);
    }
    if (truth.columns.empty()) throw_at("replay truth", file, 0, "empty (no header)");
    return truth;
}

}  // namespace

replay::replay(const std::string& manifest_path, int expected_width, int expected_height)
    : m_manifest_path(manifest_path) {
    const manifest_values m = read_manifest(manifest_path);
    m_width = m.width;
    m_height = m.height;
    m_frames = m.frames;
    m_first_number = m.first_number;
    m_calibration = m.calibration;
    m_after_last = m.after_last;
    if ((expected_width > 0 && expected_width != m_width) ||
        (expected_height > 0 && expected_height != m_height))
        manifest_error(manifest_path, 0,
                       "image size " + std::to_string(m_width) + "x" + std::to_string(m_height) +
                           " does not match the sensor's active size " +
                           std::to_string(expected_width) + "x" + std::to_string(expected_height));
    for (int side = 0; side < 2; ++side) {
        const file_pattern& p = m.patterns[side];
        m_pattern[side] = name_pattern{p.prefix, p.suffix, p.zero_pad, p.fixed};
        check_frame_files(manifest_path, m, side, [&](int frame) {
            return m_pattern[side].format(m_first_number + frame);
        });
    }
    if (!m.truth_path.empty()) m_truth = read_truth_csv(m.truth_path, m_frames);
    check_object_columns(m.truth_path, m_truth);
}

bool replay::object_truth(int frame, replay_object_truth* out) const {
    const auto has = [this](const char* column) {
        for (const std::string& c : m_truth.columns)
            if (c == column) return true;
        return false;
    };
    if (!m_truth.rows.count(frame)) return false;
    replay_object_truth t;
    t.has_point = has("x_mm");  // x, y, z come together (checked at load)
    t.has_pixel = has("u_right_px") || t.has_point;
    if (!t.has_point && !t.has_pixel) return false;
    ball_truth& b = t.ball;
    if (t.has_point) {
        b.centre_m = {m_truth.value(frame, "x_mm") / 1000.0, m_truth.value(frame, "y_mm") / 1000.0,
                      m_truth.value(frame, "z_mm") / 1000.0};
        b.visible_mean_depth_m =
            has("z_visible_mm") ? m_truth.value(frame, "z_visible_mm") / 1000.0 : b.centre_m.z;
        b.disparity_visible_px =
            m_calibration.focal_px * m_calibration.baseline_m / b.visible_mean_depth_m;
    }
    const vec2 pixel = has("u_right_px") ? vec2{m_truth.value(frame, "u_right_px"),
                                                m_truth.value(frame, "v_right_px")}
                                         : camera(camera_id::right).project(b.centre_m);
    b.right.valid = true;
    b.right.ellipse_centre = b.right.point_centre = pixel;
    // A one-pixel box at the point: the scoring's "object in the right view".
    b.right.pixel_box = {static_cast<int>(std::lround(pixel.x)),
                         static_cast<int>(std::lround(pixel.y)), 1, 1};
    *out = t;
    return true;
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
        rgb_image img = read_image_rgb(file);
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
