// Child-process launch and output parsing for the llvmpipe runner (see peer_child.h).
#include "peer_child.h"

#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "util/error.h"

extern char** environ;

namespace ontile::peer {
namespace {

// The parent's environment with `overrides` (NAME=value) replacing variables of the same name.
std::vector<std::string> child_environment(const std::vector<std::string>& overrides) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    bool replaced = false;
    for (const std::string& o : overrides) replaced |= o.compare(0, name.size() + 1, name + "=") == 0;
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), overrides.begin(), overrides.end());
  return env;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (std::string& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

}  // namespace

LlvmpipeRun run_llvmpipe(const LlvmpipeRequest& r) {
  std::vector<std::string> args = {r.runner.string(), "--scene", r.scene.string(), "--size",
                                   std::to_string(r.width_px) + "x" + std::to_string(r.height_px),
                                   "--frames", std::to_string(r.frames), "--pipeline", r.pipeline};
  if (!r.color_png.empty()) args.insert(args.end(), {"--color", r.color_png.string()});
  if (!r.primitive_ids_exr.empty()) args.insert(args.end(), {"--primitive-ids", r.primitive_ids_exr.string()});
  if (!r.edges_png.empty()) args.insert(args.end(), {"--edges", r.edges_png.string()});
  std::vector<std::string> env = child_environment(
      {"LP_NUM_THREADS=" + std::to_string(r.threads), "EGL_PLATFORM=surfaceless", "LIBGL_ALWAYS_SOFTWARE=1",
       "GALLIUM_DRIVER=llvmpipe"});
  std::vector<char*> argv = c_strings(args), envp = c_strings(env);

  int fds[2];
  if (pipe(fds) != 0) throw Error("llvmpipe runner: pipe() failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (spawned != 0) {
    close(fds[0]);
    throw Error(r.runner.string() + ": cannot start (" + std::strerror(spawned) + ")");
  }
  std::string output;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) output.append(buf, static_cast<size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);

  LlvmpipeRun run;
  bool median = false, min = false;
  std::istringstream lines(output);
  std::string line, last;
  while (std::getline(lines, line)) {
    if (!line.empty()) last = line;
    if (line.rfind("median_ms: ", 0) == 0) median = (run.times.median_ms = std::atof(line.c_str() + 11)) > 0.0;
    if (line.rfind("min_ms: ", 0) == 0) min = (run.times.min_ms = std::atof(line.c_str() + 8)) > 0.0;
    if (line.rfind("cores_busy: ", 0) == 0) run.times.cores_busy = std::atof(line.c_str() + 12);
    if (line.rfind("cpu_ms_per_frame: ", 0) == 0) run.times.cpu_ms_per_frame = std::atof(line.c_str() + 18);
    if (line.rfind("renderer: ", 0) == 0) run.renderer = line.substr(10);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kLlvmpipeUnavailableExit) {
    throw LlvmpipeUnavailable(r.runner.string() + ": " + (last.empty() ? "EGL or llvmpipe unavailable" : last));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !median || !min) {
    throw Error(r.runner.string() + " (" + r.pipeline + ", LP_NUM_THREADS=" + std::to_string(r.threads) + ", " +
                r.scene.string() + ") failed: " + (last.empty() ? "no output" : last));
  }
  return run;
}

}  // namespace ontile::peer
