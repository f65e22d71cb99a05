// A user's own golden cases (`ontile golden --cases FILE.json`): scenes, pipelines, options,
// sizes, reference images and tolerances read from a JSON file (schema: docs/golden.md).
#pragma once
#include <filesystem>
#include <vector>

#include "golden/golden_images.h"

namespace ontile {

// Reads and checks the file: relative scene and reference paths are resolved against the file's
// folder; every scene must exist. Throws Error("FILE: problem") for a missing or malformed file,
// an unknown or mistyped key, a bad value or a duplicate case name.
std::vector<GoldenCase> read_golden_cases_file(const std::filesystem::path& json_file);

}  // namespace ontile
