// The pipeline comparison benchmarks (pipeline_bench.cpp), registered by the benchmarks' main
// once every pipeline has registered itself.
#pragma once

namespace ontile {

// Pipeline/SCENE/PIPELINE for every scene of the comparison and every registered pipeline.
void register_pipeline_benchmarks();

}  // namespace ontile
