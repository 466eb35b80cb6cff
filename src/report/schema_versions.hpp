// The versions of the JSON documents that sfcv prints besides `check --json`
// (share/sfcv/{info,lint,query,rsg}.schema.json): bumped when a key changes meaning or
// disappears, so that a consumer can refuse a document it does not know.
#pragma once

namespace sfcv::report {

inline constexpr const char* kSummaryJsonSchemaVersion = "1.0";

}  // namespace sfcv::report
