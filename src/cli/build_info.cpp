#include "cli/build_info.hpp"

#include <bdd.h>

#include <cadical.hpp>

#include "cli/commands.hpp"

namespace sfcv::cli {

namespace {

/// "sc2021 (libcadical-dev 1.5.3-2)": the library's own word and the Debian package built
/// against (CMakeLists.txt asks dpkg at configure time).
std::string with_package(std::string version, const char* package, const char* package_version) {
  if (*package_version) version += std::string(" (") + package + " " + package_version + ")";
  return version;
}

}  // namespace

report::Settings library_versions() {
  const int buddy = bdd_versionnum();  // major * 10 + minor ("2.4" is 24)
  return {{"buddy", with_package(std::to_string(buddy / 10) + "." + std::to_string(buddy % 10),
                                 "libbdd-dev", SFCV_PACKAGE_LIBBDD_DEV)},
          {"cadical", with_package(CaDiCaL::Solver::version(), "libcadical-dev",
                                   SFCV_PACKAGE_LIBCADICAL_DEV)}};
}

std::string version_text() {
  std::string out = "sfcv " + report::build_version() + "\ncommit " + report::build_commit() + "\n";
  for (const auto& [name, version] : library_versions())
    out += (name == "buddy"     ? "BuDDy "
            : name == "cadical" ? "CaDiCaL "
                                : name + " ") +
           version + "\n";
  return out;
}

report::Provenance run_provenance() {
  return report::make_provenance(global_options().argv, library_versions());
}

}  // namespace sfcv::cli
