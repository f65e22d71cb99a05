// The options of ontile.render(options={...}): the `ontile render` flags by their names with
// underscores (tile, budget, arch, render_graph, gpu, idvs, ...) and `set` for the pipeline's
// --set options, checked against the same ranges and choices as the CLI. A `gpu` preset applies
// first, whatever the dictionary's order, and explicit keys override it, as on the CLI.
#pragma once
#include <string>

#include <pybind11/pybind11.h>

#include "pipelines/kit/render_frame.h"

namespace ontile::python {

struct ParsedOptions {
  RenderSettings settings;
  bool tile_report = false;  // --tiles
  std::string gpu;           // --gpu preset, empty without it
};

// Throws ontile::Error (ValueError in Python) naming the key for an unknown key or bad value.
ParsedOptions parse_render_options(const pybind11::dict& options, ParsedOptions parsed);

}  // namespace ontile::python
