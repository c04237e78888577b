// Scene replay (model/scene/replay.h) and PNG I/O (model/scene/png_io.h):
// replayed frames are exactly the files' pixels as OpenCV reads them (files
// written by OpenCV, and real video frames from shared/data), the calibration
// and ground-truth CSV are parsed, and every error case gives a clear error.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "model/scene/png_io.h"
#include "model/scene/replay.h"
#include "tests/support/data_path.h"

namespace fs = std::filesystem;
using scene::camera_id;

namespace {

// A fresh temporary folder per test, removed at the end.
struct temp_dir {
    fs::path path;
    explicit temp_dir(const std::string& tag)
        : path(fs::temp_directory_path() /
               ("stereosim_replay_" + tag + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~temp_dir() { fs::remove_all(path); }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

void write_text(const std::string& file, const std::string& text) {
    std::ofstream(file) << text;
}

// Number of pixels where the replayed frame differs from OpenCV's reading of
// the same file (BGR -> RGB; gray replicated, alpha dropped, as IMREAD_COLOR).
long differing_pixels(const scene::rgb_image& got, const std::string& file) {
    const cv::Mat bgr = cv::imread(file, cv::IMREAD_COLOR);
    EXPECT_FALSE(bgr.empty()) << file;
    EXPECT_EQ(got.width, bgr.cols);
    EXPECT_EQ(got.height, bgr.rows);
    if (bgr.empty() || got.width != bgr.cols || got.height != bgr.rows) return -1;
    long bad = 0;
    for (int y = 0; y < bgr.rows; ++y)
        for (int x = 0; x < bgr.cols; ++x) {
            const cv::Vec3b v = bgr.at<cv::Vec3b>(y, x);
            const dsp::rgb8 p = got.at(x, y);
            bad += p.r != v[2] || p.g != v[1] || p.b != v[0];
        }
    return bad;
}

const char* calibration_lines =
    "focal_px 789.5\nbaseline_m 0.12\nprincipal_left 319.5 239.5\nprincipal_right 321.25 238\n";

// Expects the manifest (or reading frame 0) to fail with `expected` in the message.
void expect_error(const std::string& manifest, const std::string& expected, int width = 0,
                  int height = 0) {
    try {
        scene::replay r(manifest, width, height);
        r.frame(camera_id::left, 0);
        ADD_FAILURE() << "no error, expected one containing: " << expected;
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
            << "error was: " << e.what() << "\nexpected to contain: " << expected;
    }
}

}  // namespace

TEST(Replay, ReproducesTheFilesPixelsExactly) {
    temp_dir dir("exact");
    cv::RNG rng(77);
    for (int k = 0; k < 3; ++k) {
        cv::Mat bgr(12, 16, CV_8UC3), gray(12, 16, CV_8UC1);
        rng.fill(bgr, cv::RNG::UNIFORM, 0, 256);
        rng.fill(gray, cv::RNG::UNIFORM, 0, 256);
        if (k == 1) {  // an RGBA file: alpha is dropped
            cv::Mat bgra;
            cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
            rng.fill(bgra.reshape(1), cv::RNG::UNIFORM, 0, 256);
            ASSERT_TRUE(cv::imwrite(dir / ("L" + std::to_string(10 + k) + ".png"), bgra));
        } else {
            ASSERT_TRUE(cv::imwrite(dir / ("L" + std::to_string(10 + k) + ".png"), bgr));
        }
        ASSERT_TRUE(cv::imwrite(dir / ("R_" + std::to_string(10 + k) + "_g.png"), gray));
    }
    write_text(dir / "seq.txt",
               std::string("stereosim_replay 1\n# comment line\nsize 16 12\n") +
                   "frames 3   # trailing comment\nleft L%d.png\nright R_%02d_g.png\n"
                   "first_number 10\n" +
                   calibration_lines);
    scene::replay r(dir / "seq.txt", 16, 12);
    EXPECT_EQ(r.frame_count(), 3);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(r.path(camera_id::left, k), dir / ("L" + std::to_string(10 + k) + ".png"));
        EXPECT_EQ(differing_pixels(r.frame(camera_id::left, k), r.path(camera_id::left, k)), 0)
            << k;
        EXPECT_EQ(differing_pixels(r.frame(camera_id::right, k), r.path(camera_id::right, k)), 0)
            << k;
    }
    // Gray files read as R = G = B.
    const scene::rgb_image& g = r.frame(camera_id::right, 0);
    for (const dsp::rgb8& p : g.pixels) ASSERT_TRUE(p.r == p.g && p.g == p.b);
    // Calibration -> pinhole cameras in the right camera's world frame.
    EXPECT_DOUBLE_EQ(r.calibration().focal_px, 789.5);
    const scene::pinhole_camera left = r.camera(camera_id::left),
                                right = r.camera(camera_id::right);
    EXPECT_DOUBLE_EQ(left.centre.x, -0.12);
    EXPECT_DOUBLE_EQ(right.centre.x, 0.0);
    EXPECT_DOUBLE_EQ(right.cx, 321.25);
    EXPECT_DOUBLE_EQ(right.cy, 238.0);
    EXPECT_DOUBLE_EQ(left.cy, 239.5);
    EXPECT_FALSE(r.has_truth());
}

// Real video frames (OpenCV's vtest, 768 x 576 RGB PNG): left = frames 0..3,
// right = frames 1..4 through absolute file patterns.
TEST(Replay, RealVideoFramesFromSharedData) {
    temp_dir dir("real");
    const std::string frames = test_support::data_path("opencv_vtest/frames/");
    write_text(dir / "seq.txt", "stereosim_replay 1\nsize 768 576\nframes 4\nleft " + frames +
                                    "vtest_%04d.png\nright " + frames + "vtest_%04d.png\n" +
                                    calibration_lines + "after_last loop\n");
    // The right camera's files are shifted by one: a second manifest.
    write_text(dir / "seq_r.txt",
               "stereosim_replay 1\nsize 768 576\nframes 4\nfirst_number 1\nleft " + frames +
                   "vtest_%04d.png\nright " + frames + "vtest_%04d.png\n" + calibration_lines);
    scene::replay r(dir / "seq.txt", 768, 576);
    scene::replay shifted(dir / "seq_r.txt");
    long total_bad = 0;
    for (int k = 0; k < 4; ++k) {
        total_bad += differing_pixels(r.frame(camera_id::left, k),
                                      frames + "vtest_000" + std::to_string(k) + ".png");
        total_bad += differing_pixels(shifted.frame(camera_id::right, k),
                                      frames + "vtest_000" + std::to_string(k + 1) + ".png");
    }
    EXPECT_EQ(total_bad, 0);
    // after_last loop: frame 5 is frame 1.
    EXPECT_EQ(r.path(camera_id::left, 5), frames + "vtest_0001.png");
    std::printf("4 + 4 real 768x576 frames replayed, %ld pixels differ from OpenCV's reading\n",
                total_bad);
    // The sensor profile needs 640 x 480: a clear error, not a crop.
    expect_error(dir / "seq.txt",
                 "image size 768x576 does not match the sensor's active size 640x480", 640, 480);
}

TEST(Replay, GroundTruthCsv) {
    temp_dir dir("truth");
    cv::Mat img(4, 6, CV_8UC3, cv::Scalar(1, 2, 3));
    for (int k = 0; k < 2; ++k)
        ASSERT_TRUE(cv::imwrite(dir / ("f" + std::to_string(k) + ".png"), img));
    write_text(dir / "truth.csv",
               "frame, x_m ,y_m,z_m,surface_z_m\n0,0.1,-0.2,3.0,2.97\n\n1,0.15,-0.2,2.9,2.87\n");
    write_text(dir / "seq.txt", std::string("stereosim_replay 1\nsize 6 4\nframes 2\nleft f%d.png\n"
                                            "right f%d.png\ntruth truth.csv\n") +
                                    calibration_lines);
    scene::replay r(dir / "seq.txt");
    ASSERT_TRUE(r.has_truth());
    EXPECT_EQ(r.truth().columns.size(), 5u);
    EXPECT_DOUBLE_EQ(r.truth().value(0, "x_m"), 0.1);
    EXPECT_DOUBLE_EQ(r.truth().value(1, "z_m"), 2.9);
    EXPECT_DOUBLE_EQ(r.truth().value(1, "surface_z_m"), 2.87);
    EXPECT_THROW(r.truth().value(2, "x_m"), std::out_of_range);
    EXPECT_THROW(r.truth().value(0, "w_m"), std::out_of_range);
}

TEST(Replay, ErrorCasesGiveClearErrors) {
    temp_dir dir("errors");
    cv::Mat img(12, 16, CV_8UC3, cv::Scalar(9, 8, 7));
    for (int k = 0; k < 3; ++k)
        ASSERT_TRUE(cv::imwrite(dir / ("a" + std::to_string(k) + ".png"), img));
    ASSERT_TRUE(cv::imwrite(dir / "small0.png", cv::Mat(10, 20, CV_8UC3, cv::Scalar(0))));
    ASSERT_TRUE(cv::imwrite(dir / "deep0.png", cv::Mat(12, 16, CV_16UC3, cv::Scalar(1000))));
    ASSERT_TRUE(cv::imwrite(dir / "photo.jpg", img));
    fs::copy_file(dir / "photo.jpg", dir / "jpeg0.png");
    const std::string head = "stereosim_replay 1\nsize 16 12\nframes 3\n";
    const std::string good = head + "left a%d.png\nright a%d.png\n" + calibration_lines;
    const auto manifest = [&](const std::string& name, const std::string& text) {
        write_text(dir / name, text);
        return dir / name;
    };

    scene::replay ok(manifest("good.txt", good));  // the base case loads
    EXPECT_EQ(ok.frame_count(), 3);

    expect_error(dir / "absent.txt", "absent.txt: cannot open");
    expect_error(manifest("empty.txt", "# nothing\n"), "empty");
    expect_error(manifest("head.txt", "stereosim_replay 2\n" + good.substr(head.find('\n') + 1)),
                 "head.txt:1: the first line must be 'stereosim_replay 1'");
    expect_error(manifest("unknown.txt", head + "focal 789\n" + good.substr(head.size())),
                 "unknown.txt:4: unknown key 'focal'");
    expect_error(manifest("twice.txt", good + "frames 3\n"), "key 'frames' given twice");
    expect_error(manifest("nan.txt", head + "left a%d.png\nright a%d.png\nfocal_px 7x9\n"),
                 "nan.txt:6: '7x9' is not a number");
    expect_error(manifest("args.txt", good + "size 16\n"), "given twice");
    expect_error(manifest("args2.txt", "stereosim_replay 1\nsize 16\n"),
                 "'size' takes 2 value(s), got 1");
    expect_error(manifest("missing.txt", head + "left a%d.png\nright a%d.png\nfocal_px 700\n"
                                                "principal_left 1 1\nprincipal_right 1 1\n"),
                 "missing required key 'baseline_m'");
    // A file with no %d is that file for every frame (a pair held): here missing.
    expect_error(manifest("pattern.txt", head + "left a.png\nright a%d.png\n" + calibration_lines),
                 "left frame 0: image '" + (dir / "a.png") + "': cannot open");
    expect_error(
        manifest("pattern2.txt", head + "left a%d_%d.png\nright a%d.png\n" + calibration_lines),
        "has more than one %d");
    // A missing image file: frames 4 but only 3 exist.
    expect_error(manifest("short.txt",
                          "stereosim_replay 1\nsize 16 12\nframes 4\nleft a%d.png\n"
                          "right a%d.png\n" +
                              std::string(calibration_lines)),
                 "left frame 3: image '" + (dir / "a3.png") + "': cannot open: No such file");
    // An image whose size is not the manifest's.
    expect_error(manifest("size.txt",
                          "stereosim_replay 1\nsize 16 12\nframes 1\nleft a%d.png\n"
                          "right small%d.png\n" +
                              std::string(calibration_lines)),
                 "right frame 0 '" + (dir / "small0.png") + "' is 20x10, the manifest says 16x12");
    // A JPEG is read whatever its name (told by its signature, as OpenCV
    // wrote it: the same pixels within the codec's loss); a text file is none.
    {
        scene::replay jpeg(manifest("jpeg.txt",
                                    "stereosim_replay 1\nsize 16 12\nframes 1\n"
                                    "left jpeg%d.png\nright a%d.png\n" +
                                        std::string(calibration_lines)));
        const scene::rgb_image& f = jpeg.frame(camera_id::left, 0);
        EXPECT_NEAR(f.pixels[0].r, 7, 2);  // cv::Scalar is B, G, R
        EXPECT_NEAR(f.pixels[0].b, 9, 2);
    }
    write_text(dir / "text0.png", "not an image");
    expect_error(manifest("text.txt",
                          "stereosim_replay 1\nsize 16 12\nframes 1\nleft text%d.png\n"
                          "right a%d.png\n" +
                              std::string(calibration_lines)),
                 "neither a PNG nor a JPEG file");
    expect_error(manifest("deep.txt",
                          "stereosim_replay 1\nsize 16 12\nframes 1\nleft deep%d.png\n"
                          "right a%d.png\n" +
                              std::string(calibration_lines)),
                 "16-bit PNG");
    expect_error(manifest("policy.txt", good + "after_last wrap\n"),
                 "after_last must be error, hold or loop");
    // Ground-truth CSV errors.
    const auto with_truth = [&](const std::string& name, const std::string& csv) {
        write_text(dir / (name + ".csv"), csv);
        return manifest(name + ".txt", good + "truth " + name + ".csv\n");
    };
    expect_error(with_truth("nocol", "x_m,y_m\n0.1,0.2\n"), "no 'frame' column");
    expect_error(with_truth("fields", "frame,x_m\n0,0.1,9\n"),
                 "fields.csv:2: 3 fields, the header has 2");
    expect_error(with_truth("nan", "frame,x_m\n0,abc\n"), "nan.csv:2: 'abc' is not a number");
    expect_error(with_truth("dup", "frame,x_m\n0,1\n0,2\n"), "dup.csv:3: frame 0 listed twice");
    expect_error(with_truth("range", "frame,x_m\n3,1\n"), "frame '3' is not 0..2");
    expect_error(manifest("nocsv.txt", good + "truth absent.csv\n"), "absent.csv: cannot open");
    // Beyond the sequence with after_last error (the default).
    EXPECT_THROW(ok.frame(camera_id::left, 3), std::out_of_range);
    try {
        ok.frame(camera_id::right, 7);
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("frame 7 asked, the sequence has 3"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Replay, HoldAndLoopPolicies) {
    temp_dir dir("policy");
    for (int k = 0; k < 3; ++k)
        ASSERT_TRUE(cv::imwrite(dir / ("p" + std::to_string(k) + ".png"),
                                cv::Mat(2, 2, CV_8UC3, cv::Scalar(k, k, k))));
    const std::string base = std::string(
                                 "stereosim_replay 1\nsize 2 2\nframes 3\nleft p%d.png\n"
                                 "right p%d.png\n") +
                             calibration_lines;
    write_text(dir / "hold.txt", base + "after_last hold\n");
    write_text(dir / "loop.txt", base + "after_last loop\n");
    scene::replay hold(dir / "hold.txt"), loop(dir / "loop.txt");
    EXPECT_EQ(hold.frame(camera_id::left, 10).at(0, 0).r, 2);
    EXPECT_EQ(loop.frame(camera_id::left, 10).at(0, 0).r, 1);
    EXPECT_EQ(loop.frame(camera_id::right, 3).at(1, 1).g, 0);
}

TEST(PngIo, WrittenFilesReadBackByOpenCvAndUs) {
    temp_dir dir("png");
    scene::rgb_image rgb(7, 5);
    scene::gray_image gray(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            rgb.at(x, y) = {static_cast<uint8_t>(x * 30), static_cast<uint8_t>(y * 50),
                            static_cast<uint8_t>(x * y * 9)};
            gray.at(x, y) = static_cast<uint8_t>(x * 36 + y);
        }
    scene::write_png(dir / "rgb.png", rgb);
    scene::write_png(dir / "gray.png", gray);
    EXPECT_EQ(differing_pixels(rgb, dir / "rgb.png"), 0);
    const cv::Mat g = cv::imread(dir / "gray.png", cv::IMREAD_UNCHANGED);
    ASSERT_EQ(g.type(), CV_8UC1);
    long bad = 0;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) bad += g.at<uint8_t>(y, x) != gray.at(x, y);
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(scene::read_png_gray(dir / "gray.png").pixels, gray.pixels);
    EXPECT_EQ(scene::read_png_info(dir / "rgb.png").channels, 3);
    EXPECT_THROW(scene::read_png_gray(dir / "rgb.png"), std::runtime_error);
}
