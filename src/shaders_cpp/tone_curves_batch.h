// The tone curves of tone_curves.h over a whole fragment batch on SIMD lanes, with the scalar
// curves' float operations in the same order, so every bit matches theirs.
#pragma once
#include "raster/shader_interface.h"

namespace ontile {

// rgba[c][f] for channels 0-2 := tonemap_aces_fitted (or tonemap_reinhard) of
// (rgba[0][f], rgba[1][f], rgba[2][f]) x exposure, and rgba[3][f] := 1, for f < count (a
// multiple of 16).
void tonemap_aces_fitted_batch(float (&rgba)[4][kBatchFragments], float exposure, int count);
void tonemap_reinhard_batch(float (&rgba)[4][kBatchFragments], float exposure, int count);

}  // namespace ontile
