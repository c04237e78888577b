// The sensor's outputs during one pixel clock (PCLK itself aside), as one
// word. Two-state: when valid is low the data bus would be tri-stated; it
// then reads 0.
#pragma once

#include <cstdint>

namespace sensor {

struct pin_word {
    static constexpr uint16_t data_mask = 0x00FF;
    static constexpr uint16_t href_bit = 1u << 8;
    static constexpr uint16_t vsync_bit = 1u << 9;
    static constexpr uint16_t valid_bit = 1u << 10;
    // Frame identity: held through each frame, it toggles from one frame to
    // the next; a repeated frame carries the repeated one's (docs/sensor.md).
    static constexpr uint16_t fodd_bit = 1u << 11;

    uint16_t bits = 0;

    uint8_t data() const { return static_cast<uint8_t>(bits & data_mask); }
    bool href() const { return (bits & href_bit) != 0; }
    bool vsync() const { return (bits & vsync_bit) != 0; }
    bool valid() const { return (bits & valid_bit) != 0; }
    bool fodd() const { return (bits & fodd_bit) != 0; }
    friend bool operator==(pin_word a, pin_word b) { return a.bits == b.bits; }
    friend bool operator!=(pin_word a, pin_word b) { return a.bits != b.bits; }
};

}  // namespace sensor
