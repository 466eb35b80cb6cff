#include "report/provenance.hpp"

#include <chrono>
#include <ctime>
#include <fstream>

#include "report/sha256.hpp"
#include "report/text_encoding.hpp"

namespace sfcv::report {

Provenance make_provenance(std::vector<std::string> command_line, Settings libraries) {
  Provenance p;
  p.version = build_version();
  p.commit = build_commit();
  p.libraries = std::move(libraries);
  p.command_line = std::move(command_line);
  p.date = utc_now_iso8601();
  return p;
}

InputFileDigest digest_file(const std::string& path) {
  InputFileDigest d;
  d.path = path;
  std::ifstream in(path, std::ios::binary);
  if (!in) return d;
  Sha256 h;
  std::string buf(1 << 16, '\0');
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    h.update(std::string_view(buf.data(), n));
    d.bytes += n;
  }
  if (in.bad()) return {path, "", 0};
  static const char* digits = "0123456789abcdef";
  for (auto b : h.finish()) {
    d.sha256 += digits[b >> 4];
    d.sha256 += digits[b & 15];
  }
  return d;
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

std::string shell_words(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    const bool plain = !w.empty() && w.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyz"
                                         "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789-_./=:,+@%") == std::string::npos;
    if (plain) {
      out += w;
      continue;
    }
    out += '\'';
    for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

namespace {

nlohmann::json settings_json(const Settings& s) {
  auto j = nlohmann::json::object();
  for (const auto& [k, v] : s) j[k] = v;
  return j;
}

Settings settings_from(const nlohmann::json& j) {
  Settings s;
  if (j.is_object())
    for (const auto& [k, v] : j.items())
      if (v.is_string()) s.emplace_back(k, v.get<std::string>());
  return s;
}

std::string settings_words(const Settings& s) {
  std::string out;
  for (const auto& [k, v] : s) out += (out.empty() ? "" : " ") + k + "=" + shell_words({v});
  return out;
}

}  // namespace

nlohmann::json provenance_json(const Provenance& p) {
  using nlohmann::json;
  json j;
  j["tool"] = p.tool;
  j["version"] = p.version;
  j["commit"] = p.commit;
  j["libraries"] = settings_json(p.libraries);
  j["command_line"] = p.command_line;
  j["date"] = p.date;
  j["inputs"] = json::array();
  for (const auto& in : p.inputs)
    j["inputs"].push_back({{"path", in.path},
                           {"sha256", in.sha256.empty() ? json(nullptr) : json(in.sha256)},
                           {"bytes", in.bytes}});
  j["engine"] = p.engine;
  j["settings"] = settings_json(p.settings);
  make_valid_utf8(j);  // paths and arguments are bytes
  return j;
}

Provenance provenance_from_json(const nlohmann::json& j) {
  Provenance p;
  if (!j.is_object()) return p;
  auto str = [&j](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  p.tool = str("tool");
  p.version = str("version");
  p.commit = str("commit");
  p.date = str("date");
  p.engine = str("engine");
  if (const auto it = j.find("libraries"); it != j.end()) p.libraries = settings_from(*it);
  if (const auto it = j.find("settings"); it != j.end()) p.settings = settings_from(*it);
  if (const auto it = j.find("command_line"); it != j.end() && it->is_array())
    for (const auto& w : *it)
      if (w.is_string()) p.command_line.push_back(w.get<std::string>());
  if (const auto it = j.find("inputs"); it != j.end() && it->is_array())
    for (const auto& in : *it) {
      if (!in.is_object()) continue;
      InputFileDigest d;
      d.path = in.value("path", std::string());
      if (in.contains("sha256") && in["sha256"].is_string()) d.sha256 = in["sha256"];
      d.bytes = in.value("bytes", std::uint64_t{0});
      p.inputs.push_back(std::move(d));
    }
  return p;
}

std::string provenance_text(const Provenance& p) {
  std::string out = "# " + p.tool + " " + p.version + " (commit " + p.commit;
  for (const auto& [name, version] : p.libraries) out += ", " + name + " " + version;
  out += "), " + p.date + "\n";
  if (!p.command_line.empty()) out += "# command: " + shell_words(p.command_line) + "\n";
  for (const auto& in : p.inputs)
    out += "# input: " + in.path + " " +
           (in.sha256.empty() ? std::string("(unreadable)") : "sha256:" + in.sha256) + "\n";
  out += "# engine: " + (p.engine.empty() ? std::string("?") : p.engine);
  if (!p.settings.empty()) out += "; settings: " + settings_words(p.settings);
  out += "\n";
  return valid_utf8(out);
}

std::string run_digest(const Provenance& p) {
  std::string text;
  // Leave out the program's own path: the same run from another directory is the same run.
  for (std::size_t i = 1; i < p.command_line.size(); ++i) text += p.command_line[i] + '\0';
  return sha256_hex(text).substr(0, 8);
}

}  // namespace sfcv::report
