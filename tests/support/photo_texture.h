// A real image file as a texture for the scene renderer's background plane
// (scene::texture_image; the scene library reads no files itself).
#pragma once

#include <memory>
#include <string>

#include "model/scene/texture.h"

namespace testsupport {

// The image at `path` (any format OpenCV reads), RGB; null if unreadable.
std::shared_ptr<const scene::texture_image> load_photo_texture(const std::string& path);

}  // namespace testsupport
