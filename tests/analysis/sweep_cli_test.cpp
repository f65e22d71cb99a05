// `ontile sweep` as a user runs it: a CSV with the documented header and one row per setting in
// order, a PNG plot, and one error line with a non-zero exit (and no output files) for bad
// arguments.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "support/cli_runner.h"
#include "analysis/sweep_csv.h"

namespace ontile {
namespace {

namespace fs = std::filesystem;

using ontile::test::CliRun;
using ontile::test::run_cli;

fs::path temp_folder() { return ontile::test::temp_folder("ontile_sweep_cli_test"); }

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, sep)) fields.push_back(field);
  if (!line.empty() && line.back() == sep) fields.push_back("");
  return fields;
}

const std::string kDemo = std::string(ONTILE_SOURCE_DIR) + "/scenes/demo.glb";

TEST(SweepCli, WritesTheCsvRowsAndThePlot) {
  const fs::path dir = temp_folder();
  const fs::path csv = dir / "sweep.csv", svg = dir / "sweep.svg";
  const CliRun r = run_cli("sweep --scene " + kDemo + " --size 64x36 --frames 1 --spp 4 --threads 2 --csv " +
                           csv.string() + " --plot " + svg.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Pareto front"), std::string::npos) << r.output;

  std::ifstream f(csv);
  std::vector<std::string> lines;
  for (std::string line; std::getline(f, line);) lines.push_back(line);
  const std::vector<SweepSetting> settings = sweep_settings();
  ASSERT_EQ(lines.size(), settings.size() + 1);
  const std::vector<std::string> columns = sweep_csv_columns();
  EXPECT_EQ(split(lines[0], ','), columns);
  auto column = [&](const std::string& name) {
    return static_cast<size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  int pareto = 0;
  for (size_t i = 0; i < settings.size(); ++i) {
    const std::vector<std::string> fields = split(lines[i + 1], ',');
    ASSERT_EQ(fields.size(), columns.size()) << lines[i + 1];
    EXPECT_EQ(fields[column("setting")], settings[i].name);
    EXPECT_EQ(fields[column("width_px")], "64");
    EXPECT_EQ(fields[column("reference_spp")], "4");
    const bool msaa = settings[i].options.msaa_samples > 1;
    EXPECT_EQ(fields[column("id_mismatch_vs_default")].empty(), msaa) << settings[i].name;
    const bool normals = settings[i].options.normals.has_value();
    EXPECT_EQ(fields[column("normal_mean_error_deg")].empty(), !normals) << settings[i].name;
    EXPECT_EQ(fields[column("normal_storage_max_error_deg")].empty(), !normals) << settings[i].name;
    EXPECT_EQ(fields[column("normal_buffer_bytes")] == "0", !normals) << settings[i].name;
    pareto += fields[column("pareto_time")] == "1";
  }
  // The default's ids are the baseline of that column.
  EXPECT_EQ(split(lines[1], ',')[column("id_mismatch_vs_default")], "0.000000");
  EXPECT_GE(pareto, 1);

  // The plot: a standalone 960x600 SVG with one point group per setting.
  std::ifstream plot_file(svg);
  const std::string plot((std::istreambuf_iterator<char>(plot_file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(plot.rfind("<?xml", 0), 0u);
  EXPECT_NE(plot.find("width=\"960\" height=\"600\""), std::string::npos);
  size_t points = 0;
  for (size_t at = plot.find("<g class=\"point\">"); at != std::string::npos; at = plot.find("<g class=\"point\">", at + 1)) {
    ++points;
  }
  EXPECT_EQ(points, settings.size());
  EXPECT_NE(plot.find("Pareto front"), std::string::npos);
}

TEST(SweepCli, BadArgumentsGiveOneErrorLineAndWriteNothing) {
  const fs::path dir = temp_folder() / "bad";
  const std::string outputs = " --csv " + (dir / "s.csv").string() + " --plot " + (dir / "s.svg").string();
  const std::string base = "sweep --scene " + kDemo + " --size 32x18 --frames 1";
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {base + " --spp 5" + outputs, "5"},
      {base + " --spp 4 --csv " + (dir / "s.txt").string() + " --plot " + (dir / "s.svg").string(), ".csv"},
      {base + " --spp 4 --csv " + (dir / "s.csv").string() + " --plot " + (dir / "s.png").string(), ".svg"},
      {"sweep --scene " + kDemo + " --frames 0 --spp 4" + outputs, "frames"},
  };
  for (const Case& c : cases) {
    const CliRun r = run_cli(c.args);
    EXPECT_NE(r.exit_code, 0) << c.args;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "s.csv")) << c.args;
    EXPECT_FALSE(fs::exists(dir / "s.svg")) << c.args;
  }
}

}  // namespace
}  // namespace ontile
