// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// WRC_SIMD_CLONES: compile a hot numerical function twice, for x86-64-v3 (AVX2, FMA) and for the
/// baseline, and let the loader pick the clone the processor runs (GCC function multi-versioning).
/// The binary runs on any x86-64 and the Release flags stay the default. Elsewhere (another
/// compiler or architecture) it expands to nothing and the function is compiled once.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define WRC_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define WRC_SIMD_CLONES
#endif
