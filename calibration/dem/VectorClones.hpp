#ifndef sdf_dem_VectorClones_hpp
#define sdf_dem_VectorClones_hpp

// SDF_DEM_VECTOR_CLONES before a function with a vectorisable loop: GCC compiles it once
// per vector width (AVX-512, AVX2, the baseline SSE2) and picks the clone at load time
// from the CPU (function multiversioning), so the build needs no -march. The files that
// use it are compiled without floating-point contraction (CMakeLists.txt): a fused
// multiply-add would round differently on the wider clones, and every clone must give
// the bits of the baseline.

// -DSDF_DEM_NO_VECTOR_CLONES compiles one version for the build's own target (to measure
// one vector width: e.g. with -mavx2, or none for the SSE2 baseline).

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) \
 && !defined(SDF_DEM_NO_VECTOR_CLONES)
#define SDF_DEM_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SDF_DEM_VECTOR_CLONES
#endif

#endif
