// The C firmware compiled as C++17 (-pedantic -Werror): the ABI header and a
// plugin written against it are valid in both languages.
#include "minimal_firmware.c"
