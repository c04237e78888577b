// One request to the EMIF engine: a single word (CPU) or a burst of words
// (EDMA), read into or written from a caller buffer. The caller owns the
// object and keeps it alive until the engine reports it complete; the engine
// links it into its queues intrusively (no allocation per access).
#pragma once

#include <cstdint>

namespace emif {

// Who asks for the bus (docs/emif.md, "Arbitration"). SDRAM refresh is the
// engine's own requester.
enum class requester : uint8_t { cpu = 0, edma = 1 };
inline constexpr int requester_count = 2;
const char* requester_name(requester r);

inline constexpr uint64_t not_granted = UINT64_MAX;

enum class access_status : uint8_t {
    pending,
    ok,
    address_error,       // not in EMIFA CE0..CE3, unaligned, or zero words
    unsupported_memory,  // the CE space's MTYPE is neither ASYNC32 nor SDRAM
};

struct emif_access {
    // ---- request, set by the caller ----
    requester who = requester::cpu;
    bool write = false;
    uint32_t address = 0;   // byte address of the first word, 4-byte aligned
    uint32_t words = 1;     // 32-bit words
    bool increment = true;  // false: every word at `address` (a FIFO port)
    // words * 4 bytes; word k is bytes 4k..4k+3, little endian (the C6416 is
    // little endian: byte 0 on ED[7:0]).
    uint8_t* data = nullptr;
    uint8_t be_n = 0;  // write byte enables (active low) for every word; reads drive 0
    void* user = nullptr;

    // ---- result, set by the engine (edge indices of ECLKOUT) ----
    access_status status = access_status::pending;
    uint64_t eligible_edge = 0;         // first edge at which it may win the bus
    uint64_t grant_edge = not_granted;  // edge at which it first won (turnaround or setup starts)
    uint64_t done_edge = 0;             // edge at which its last word ended (hold over)
    uint32_t words_done = 0;
    uint32_t wait_cycles = 0;        // strobe cycles added by ARDY (and injected faults)
    uint32_t turnaround_cycles = 0;  // idle cycles inserted before its words

    // ---- engine-owned ----
    emif_access* queue_next = nullptr;
};

}  // namespace emif
