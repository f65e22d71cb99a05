// Test helper: runs the built `ontile` CLI (ONTILE_CLI) as a user would, capturing its exit
// code and combined output, and gives each test file its own temporary folder. Every report a
// successful run writes is collected for the schema check (Reports.* in tests/CMakeLists.txt).
#pragma once
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ontile::test {

struct CliRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Checks a report the CLI wrote against docs/report.schema.json (tests/validate_reports.py):
// every report the suite writes through the CLI is validated where it is written.
inline void validate_report(const std::filesystem::path& report) {
  const std::string cmd = "python3 " + std::string(ONTILE_SOURCE_DIR) + "/tests/validate_reports.py " +
                          std::string(ONTILE_SOURCE_DIR) + "/docs/report.schema.json " + report.string() + " 2>&1";
  std::string output;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) output.append(buf.data(), n);
  const int status = pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ADD_FAILURE() << report << " does not match the schema:\n" << output;
}

inline CliRun run_cli(const std::string& args) {
  const std::string cmd = std::string(ONTILE_CLI) + " " + args + " 2>&1";
  CliRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (r.exit_code == 0) {
    std::istringstream words(args);
    for (std::string word; words >> word;) {
      std::string path;
      if (word == "--report" && words >> path && path != "-" && std::filesystem::exists(path)) validate_report(path);
    }
  }
  return r;
}

// <temp>/<prefix>_<pid>, created.
inline std::filesystem::path temp_folder(const std::string& prefix) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace ontile::test
