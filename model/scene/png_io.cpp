#include "model/scene/png_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

// The one translation unit with stb's implementation; static linkage keeps its
// symbols private to this file.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace scene {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw std::runtime_error("PNG '" + path + "': " + what);
}

// Opens the file and checks the 8-byte PNG signature, so a missing file, a
// JPEG with a .png name and a truncated file give distinct messages.
void check_png_file(const std::string& path) {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) fail(path, std::string("cannot open: ") + std::strerror(errno));
    static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    unsigned char head[8] = {};
    if (std::fread(head, 1, 8, f.get()) != 8 || std::memcmp(head, signature, 8) != 0)
        fail(path, "not a PNG file (bad signature)");
}

[[noreturn]] void fail_image(const std::string& path, const std::string& what) {
    throw std::runtime_error("image '" + path + "': " + what);
}

// A replay's image: a PNG, or a baseline or progressive JPEG (by signature).
void check_image_file(const std::string& path) {
    std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) fail_image(path, std::string("cannot open: ") + std::strerror(errno));
    unsigned char head[8] = {};
    const size_t n = std::fread(head, 1, 8, f.get());
    static constexpr unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    const bool is_png = n == 8 && std::memcmp(head, png, 8) == 0;
    const bool is_jpeg = n >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF;
    if (!is_png && !is_jpeg) fail_image(path, "neither a PNG nor a JPEG file (bad signature)");
}

struct stbi_deleter {
    void operator()(stbi_uc* p) const { stbi_image_free(p); }
};

std::unique_ptr<stbi_uc, stbi_deleter> load_8bit(const std::string& path, int want_channels,
                                                 png_info* info) {
    *info = read_png_info(path);
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, stbi_deleter> pixels(
        stbi_load(path.c_str(), &w, &h, &n, want_channels));
    if (!pixels) fail(path, std::string("cannot decode: ") + stbi_failure_reason());
    return pixels;
}

}  // namespace

png_info read_png_info(const std::string& path) {
    check_png_file(path);
    png_info info;
    if (!stbi_info(path.c_str(), &info.width, &info.height, &info.channels))
        fail(path, std::string("cannot read header: ") + stbi_failure_reason());
    if (stbi_is_16_bit(path.c_str())) fail(path, "16-bit PNG (only 8-bit is supported)");
    return info;
}

png_info read_image_info(const std::string& path) {
    check_image_file(path);
    png_info info;
    if (!stbi_info(path.c_str(), &info.width, &info.height, &info.channels))
        fail_image(path, std::string("cannot read header: ") + stbi_failure_reason());
    if (stbi_is_16_bit(path.c_str())) fail_image(path, "16-bit PNG (only 8-bit is supported)");
    return info;
}

rgb_image read_image_rgb(const std::string& path) {
    read_image_info(path);  // its checks: format, depth
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, stbi_deleter> pixels(stbi_load(path.c_str(), &w, &h, &n, 3));
    if (!pixels) fail_image(path, std::string("cannot decode: ") + stbi_failure_reason());
    rgb_image out(w, h);  // the decoded size, whatever the header claimed
    std::memcpy(out.pixels.data(), pixels.get(), out.pixels.size() * sizeof(dsp::rgb8));
    return out;
}

rgb_image read_png_rgb(const std::string& path) {
    png_info info;
    const auto pixels = load_8bit(path, 3, &info);
    rgb_image out(info.width, info.height);
    std::memcpy(out.pixels.data(), pixels.get(), out.pixels.size() * sizeof(dsp::rgb8));
    return out;
}

gray_image read_png_gray(const std::string& path) {
    png_info info;
    const auto pixels = load_8bit(path, 1, &info);
    if (info.channels > 2) fail(path, "colour PNG where a gray one is needed");
    gray_image out(info.width, info.height);
    std::memcpy(out.pixels.data(), pixels.get(), out.pixels.size());
    return out;
}

void write_png(const std::string& path, const rgb_image& image) {
    static_assert(sizeof(dsp::rgb8) == 3, "rgb8 must be packed R, G, B bytes");
    if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.pixels.data(),
                        image.width * 3))
        fail(path, "cannot write");
}

void write_png(const std::string& path, const gray_image& image) {
    if (!stbi_write_png(path.c_str(), image.width, image.height, 1, image.pixels.data(),
                        image.width))
        fail(path, "cannot write");
}

}  // namespace scene
