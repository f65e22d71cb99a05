// Test helper: runs the built `ontile` CLI with its standard output and standard error captured
// apart, to check the error contract (one "error: ..." line on stderr, nothing on stdout) and
// that `-` reports go to stdout alone.
#pragma once
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>

namespace ontile::test {

struct SplitRun {
  int exit_code = -1;
  std::string out, err;
};

// stderr goes through a file in `scratch`, which is removed afterwards.
inline SplitRun run_cli_split(const std::string& args, const std::filesystem::path& scratch) {
  static int counter = 0;
  const std::filesystem::path err_file = scratch / ("stderr_" + std::to_string(counter++) + ".txt");
  const std::string cmd = std::string(ONTILE_CLI) + " " + args + " 2>" + err_file.string();
  SplitRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) r.out.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream f(err_file, std::ios::binary);
  r.err.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return r;
}

}  // namespace ontile::test
