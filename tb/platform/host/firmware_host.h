// A firmware's optional host entry (include/stereosim/firmware.h,
// stereosim_fw_host) over a rendered scenario, with no sensors, card or bus:
// scene frame n is rendered, both images are mosaicked in the board's CFA
// (what the sensors deliver), and the raw pair goes to process_pair. The
// services price kernels under the run's cost model and keep the reported
// result; the bus, memory and interrupt services do nothing. The sweep's
// closed form takes a pair's processing cycles from it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/c64x/cost_model.h"
#include "model/scene/sequence.h"
#include "stereosim/firmware.h"

namespace host {

class firmware_host {
  public:
    // An instance of `entry` for `board` and the key `values` of a firmware
    // declaring `stage_count` stages; null, with one line in *error, if its
    // create refuses or the board's image is not the scenario's.
    static std::unique_ptr<firmware_host> create(const stereosim_fw_host& entry,
                                                 uint32_t stage_count, scene::scenario scenario,
                                                 const stereosim_board& board,
                                                 const std::vector<double>& values,
                                                 const c64x::cost_model& model, std::string* error);
    ~firmware_host();
    firmware_host(const firmware_host&) = delete;
    firmware_host& operator=(const firmware_host&) = delete;

    // Renders frame n and processes it as pair n: its result, or false with
    // one line in *error if the firmware reported none, more than one, or
    // used a stage it did not declare.
    bool step(int n, stereosim_result* result, std::string* error);

  private:
    firmware_host(const stereosim_fw_host& entry, uint32_t stage_count, scene::scenario scenario,
                  const stereosim_board& board, const c64x::cost_model& model);
    void serve();

    const stereosim_fw_host& m_entry;
    uint32_t m_stage_count;
    scene::sequence m_sequence;
    stereosim_board m_board;
    c64x::cost_model m_model;
    stereosim_services m_services{};
    void* m_instance = nullptr;

    scene::stereo_frame m_frame;
    scene::gray_image m_raw_left, m_raw_right;
    std::vector<stereosim_result> m_results;  // reported in the current step
    std::string m_broken;                     // the first ABI breach seen
};

}  // namespace host
