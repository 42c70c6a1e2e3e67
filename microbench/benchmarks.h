// The individual micro-benchmarks. Each builds its pass(es), runs them on the emulated GPU
// and returns one result row (see docs/microbench.md for what each one stresses).
#pragma once

#include "microbench/bench_context.h"

namespace skinsim::microbench {

// fill_rate.cpp: full-screen layers with one bilinear read each.
MicrobenchResult run_fill_blended(BenchContext& ctx);
MicrobenchResult run_fill_opaque(BenchContext& ctx);

// triangle_rate.cpp: dense grids of tiny triangles.
MicrobenchResult run_triangles_visible(BenchContext& ctx);
MicrobenchResult run_triangles_offscreen(BenchContext& ctx);
MicrobenchResult run_triangles_backface(BenchContext& ctx);

// bandwidth.cpp: DRAM-bound passes.
MicrobenchResult run_bandwidth_copy(BenchContext& ctx);
MicrobenchResult run_bandwidth_resolve(BenchContext& ctx);

// alu_rate.cpp: a long arithmetic shader.
MicrobenchResult run_alu_mad_chain(BenchContext& ctx);

}  // namespace skinsim::microbench
