// Where the shared real test data lives (../shared/data beside the repo).
#pragma once
#include <string>

namespace test_support {

// Absolute path of a file under ../shared/data, e.g. data_path("kodak_demosaic_gt/kodim19.png").
std::string data_path(const std::string& relative);

}  // namespace test_support
