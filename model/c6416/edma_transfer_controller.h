// The EDMA's transfer controller (one, ASSUMED): moves a transfer request of
// the channel controller (edma_core) array by array, through a staging
// buffer, between L2 / SDRAM, the peripheral registers and EMIFA. Plain C++:
// what it reaches is the chip's memory map (edma_memory_map); c6416_sc runs it
// on its EDMA thread, where an EMIFA access takes simulated time.
#pragma once

#include <cstdint>
#include <vector>

#include "model/c6416/edma_core.h"

namespace c6416 {

class edma_memory_map {
  public:
    virtual ~edma_memory_map() = default;
    // Bytes of L2 or SDRAM the chip holds, nullptr outside them.
    virtual uint8_t* memory(uint32_t address, uint32_t bytes) = 0;
    // Served by the chip in zero time (no EMIFA access).
    virtual bool is_local(uint32_t address) const = 0;
    virtual bool is_peripheral(uint32_t address) const = 0;
    virtual uint32_t register_read(uint32_t address) = 0;
    virtual void register_write(uint32_t address, uint32_t value) = 0;
    // One EDMA access on EMIFA: streaming_width = length for incrementing
    // addresses, the element size for a fixed one (a FIFO port).
    virtual void emifa_access(bool write, uint32_t address, uint8_t* data, uint32_t length,
                              uint32_t streaming_width) = 0;
    // An element outside the memory map: the rest of the run is dropped.
    virtual void map_error(const char* what) = 0;
};

class edma_transfer_controller {
  public:
    explicit edma_transfer_controller(edma_memory_map& map) : m_map(map) {}

    void execute(const transfer_request& r);

  private:
    void bus_run(bool write, uint32_t address, int64_t step, uint32_t elements,
                 uint32_t element_bytes, uint8_t* data);
    void read_run(uint32_t address, int64_t step, uint32_t elements, uint32_t element_bytes,
                  uint8_t* out);
    void write_run(uint32_t address, int64_t step, uint32_t elements, uint32_t element_bytes,
                   const uint8_t* in);

    edma_memory_map& m_map;
    std::vector<uint8_t> m_staging;
};

}  // namespace c6416
