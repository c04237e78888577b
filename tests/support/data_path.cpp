#include "tests/support/data_path.h"

namespace test_support {

std::string data_path(const std::string& relative) {
    return std::string(STEREOSIM_SHARED_DATA) + "/" + relative;
}

}  // namespace test_support
