// The accuracy sweep's CSV table: one header line, one line per setting (docs/accuracy.md
// documents the columns). Empty fields mean "not measured for this setting".
#pragma once
#include <string>
#include <vector>

#include "analysis/sweep_run.h"

namespace ontile {

std::vector<std::string> sweep_csv_columns();
std::string sweep_csv(const SweepResult& result);

}  // namespace ontile
