#include "tests/support/photo_texture.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace testsupport {

std::shared_ptr<const scene::texture_image> load_photo_texture(const std::string& path) {
    const cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
    if (bgr.empty()) return nullptr;
    auto tex = std::make_shared<scene::texture_image>();
    tex->width = bgr.cols;
    tex->height = bgr.rows;
    for (int y = 0; y < bgr.rows; ++y) {
        for (int x = 0; x < bgr.cols; ++x) {
            const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
            tex->pixels.push_back(dsp::rgb8{p[2], p[1], p[0]});
        }
    }
    return tex;
}

}  // namespace testsupport
