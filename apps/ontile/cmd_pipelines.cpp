// `ontile pipelines`: lists the render pipelines and what each does.
#include <cstdio>

#include "commands.h"
#include "pipelines/kit/pipeline.h"

namespace ontile::cli {

void add_pipelines_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("pipelines", "List the render pipelines");
  cmd->callback([] {
    for (const std::string& name : pipeline_names()) {
      std::printf("%-20s %s\n", name.c_str(), make_pipeline(name)->description().c_str());
    }
  });
}

}  // namespace ontile::cli
