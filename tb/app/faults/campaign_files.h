// What a campaign writes (docs/fault-contract.md "The campaign"), from the
// campaign document alone (its header and the rows of campaign.json), so
// that a campaign run in one go and the merge of its shards (`stereosim
// merge`) write the same files: campaign.json, campaign.csv, campaign.txt.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace faults {

// The document: header fields given, the counts (runs, contract_broken,
// clean_frames, clean_false_alarms) from the rows.
nlohmann::json campaign_document(const std::string& name, const std::string& shard, int seeds,
                                 int jobs, bool snapshots, double wall_s, nlohmann::json rows);

// The readable table (campaign.txt, and stdout).
std::string campaign_table(const nlohmann::json& campaign);

// campaign.json, campaign.csv and campaign.txt in `dir`.
bool write_campaign_files(const std::string& dir, const nlohmann::json& campaign,
                          std::string* error);

// The shards' documents as one (shard "1/1", rows by index, counts anew,
// wall the longest shard's); false + *error if they are not shards of one
// campaign, or if rows are missing (named with the shard they belong to).
bool merge_campaign_shards(const std::vector<nlohmann::json>& shards, nlohmann::json* merged,
                           std::string* error);

}  // namespace faults
