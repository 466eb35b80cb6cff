#pragma once
// A shard's answers, in full, inside its `sfcv check --json --shard I/N` result ("shard": see
// docs/distributed.md), so that `sfcv merge` can give the report a single run would have given:
// the CheckReport as data (traces as the packed states and inputs the engines produced, which
// only the same model built with the same options can read back), the shard's place in the
// split, and every unit of the run with its cost.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "logic/check_result.hpp"
#include "logic/work_units.hpp"
#include "report/provenance.hpp"

namespace sfcv::report {

/// The CheckReport as JSON, losslessly (report_from_json inverts it).
nlohmann::json report_to_json(const logic::CheckReport& report);
logic::CheckReport report_from_json(const nlohmann::json& j);

/// `sfcv plan --json` and the "units" of the "shard" key: [{"id", "kind", "name", "cost",
/// "shard"}] (shard: 1-based, the shard of `count` that runs it).
nlohmann::json units_json(const std::vector<logic::WorkUnit>& units, std::uint32_t count);

/// The "shard" key of a shard's result: {"index", "count", "diversify", "units" (every unit of
/// the run, units_json), "covers" (the ids this shard ran, or every id when diversified),
/// "result" (report_to_json of this shard's report), "settings" and "libraries" (the
/// provenance's, as [name, value] pairs in their order, which a JSON object does not keep)}.
nlohmann::json shard_json(const logic::ShardSpec& spec, bool diversify,
                          const std::vector<logic::WorkUnit>& units,
                          const std::vector<logic::WorkUnit>& covered,
                          const logic::CheckReport& report, const Provenance& provenance);

}  // namespace sfcv::report
