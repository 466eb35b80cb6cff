#include "cli/check_traces.hpp"

#include <filesystem>

#include "cli/exit_code.hpp"
#include "cli/output_file.hpp"
#include "report/trace_render.hpp"

namespace sfcv::cli {

namespace {

const char* extension(report::TraceFormat f) {
  switch (f) {
    case report::TraceFormat::Json:
      return ".json";
    case report::TraceFormat::Vcd:
      return ".vcd";
    case report::TraceFormat::Csv:
      return ".csv";
    default:
      return ".txt";
  }
}

}  // namespace

bool traces_on_standard_output(const TraceRequest& r) {
  if (!r.dir.empty()) return false;
  if (r.file == "-" || r.file == "/dev/stdout") return true;
  return r.file.empty() &&
         (r.format == report::TraceFormat::Vcd || r.format == report::TraceFormat::Csv);
}

void check_trace_request(const TraceRequest& r) {
  if (!r.dir.empty() && !r.file.empty())
    throw UsageError("--trace-dir and --trace-file: give one (--trace-dir writes every trace)");
  if (r.json && traces_on_standard_output(r))
    throw UsageError(
        "--json holds standard output: write the traces with --trace-dir DIR or --trace-file "
        "FILE (the JSON holds each trace too)");
  if (!r.dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(r.dir, ec);
    if (ec || !std::filesystem::is_directory(r.dir))
      throw UsageError("--trace-dir " + r.dir + ": not a directory that can be created (" +
                       ec.message() + ")");
  }
}

std::string trace_text(const logic::Trace& trace, const semantics::TransitionSystem& ts,
                       const TraceRequest& request) {
  switch (request.format) {
    case report::TraceFormat::Json:
      return report::trace_json(trace, ts);
    case report::TraceFormat::Vcd:
      return report::trace_vcd(trace, ts, {request.cycle_ms});
    case report::TraceFormat::Csv:
      return report::trace_csv(trace, ts);
    default:
      return report::trace_table(trace, ts);
  }
}

WrittenTraces write_traces(const logic::CheckReport& result, const semantics::TransitionSystem& ts,
                           const TraceRequest& request) {
  WrittenTraces out;
  std::vector<const logic::PropertyResult*> traced;
  for (const auto& r : result.results)
    if (r.trace) traced.push_back(&r);
  if (traced.empty()) return out;
  if (traces_on_standard_output(request)) {
    if (traced.size() == 1) {
      out.standard_output = trace_text(*traced[0]->trace, ts, request);
      out.where[report::property_id(*traced[0])] = "standard output";
    } else {
      out.errors.push_back(std::to_string(traced.size()) +
                           " traces, and standard output holds one: give --trace-dir DIR "
                           "(one file per property, named by its id)");
    }
    return out;
  }
  if (request.dir.empty() && request.file.empty()) return out;  // inside the text report
  for (const auto* r : traced) {
    std::string path;
    if (!request.dir.empty()) {
      path = (std::filesystem::path(request.dir) /
              (report::property_file_stem(*r) + extension(request.format)))
                 .string();
    } else if (traced.size() == 1) {
      path = request.file;
    } else {
      const std::filesystem::path f(request.file);
      path = (f.parent_path() /
              (f.stem().string() + "." + report::property_file_stem(*r) + f.extension().string()))
                 .string();
    }
    try {
      write_output({path, request.dir.empty() ? "--trace-file" : "--trace-dir"},
                   trace_text(*r->trace, ts, request));
      out.where[report::property_id(*r)] = path;
    } catch (const UsageError& e) {
      out.errors.push_back(e.what());
    }
  }
  return out;
}

}  // namespace sfcv::cli
