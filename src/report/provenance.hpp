#pragma once
// The provenance of a report: which sfcv (version, git commit, the BuDDy and CaDiCaL it was built
// with) ran which command line, when (UTC), on which input files (SHA-256), with which engine and
// settings. The CLI fills it (make_provenance); every report renders the same data: a block in
// the text, "provenance" in the JSON (and so the HTML report), properties of the JUnit suite, the
// SARIF run's invocation, artifacts and tool properties. A later merge of several runs can read
// it back from their JSON (provenance_from_json).

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sfcv::report {

/// The version of the CMake project ("0.1.0") and the git commit the build came from (40 hex
/// digits, "-dirty" when tracked files had changed; "unknown" outside a git checkout).
/// Generated at build time (cmake/BuildInfo.cmake).
std::string build_version();
std::string build_commit();
/// Where the tool is described (CMake's SFCV_INFORMATION_URI): SARIF's tool informationUri;
/// empty when the build was given none (the SARIF log then leaves it out).
std::string build_information_uri();

struct InputFileDigest {
  std::string path;    ///< as given on the command line
  std::string sha256;  ///< 64 hex digits; empty when the file could not be read
  std::uint64_t bytes = 0;
};

using Settings = std::vector<std::pair<std::string, std::string>>;  ///< in the order given

struct Provenance {
  std::string tool = "sfcv";
  std::string version;                    ///< build_version()
  std::string commit;                     ///< build_commit()
  Settings libraries;                     ///< {"buddy", "2.4"}, {"cadical", "1.5.3"}
  std::vector<std::string> command_line;  ///< argv, the program name first
  std::string date;                       ///< start of the run, UTC, ISO 8601 ("...Z")
  std::vector<InputFileDigest> inputs;    ///< the model first, then spec files
  std::string engine;                     ///< --engine as asked ("auto")
  Settings settings;                      ///< the options that shape the answers
};

/// Version, commit and the given libraries, dated now; command line, inputs and engine empty.
Provenance make_provenance(std::vector<std::string> command_line, Settings libraries = {});

/// `path`'s SHA-256 and size (read in blocks); sha256 empty when it cannot be read ("-").
InputFileDigest digest_file(const std::string& path);

/// Now, as "2026-12-06T09:33:15Z".
std::string utc_now_iso8601();

/// The command line as a shell would take it back: words with spaces or quotes single-quoted.
std::string shell_words(const std::vector<std::string>& words);

/// {"tool", "version", "commit", "libraries": {...}, "command_line": [...], "date",
///  "inputs": [{"path", "sha256", "bytes"}], "engine", "settings": {...}}
nlohmann::json provenance_json(const Provenance& p);
/// The inverse of provenance_json (missing keys stay empty): for tools that merge results.
Provenance provenance_from_json(const nlohmann::json& j);

/// Four or more lines for a text report, each starting with "# ":
///   # sfcv 0.1.0 (commit 1a2b3c4d5e6f), 2026-12-06T09:33:15Z
///   # command: sfcv check plant.st --ctl 'AG !(V2 & V4)'
///   # input: plant.st sha256:9f86d0...
///   # engine: auto; settings: semantics=iec61131 priority=standard ...
std::string provenance_text(const Provenance& p);

/// A short run label, stable for the same command line: 8 hex digits of its SHA-256.
std::string run_digest(const Provenance& p);

}  // namespace sfcv::report
