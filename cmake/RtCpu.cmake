# RT_AVX2: compile the whole project for x86-64 CPUs with AVX2 and FMA (Intel since 2013, AMD
# since 2015). The voxel walks gain 5-23 % and the BVH 3-7 % from AVX2 (docs/accelerators.md,
# "Built for AVX2"), mostly from one-instruction rounding (the DDDA's floor) and three-operand
# arithmetic. FMA only where the code asks for it: the float pre-filters' multiply-and-add steps
# (accel/float_prefilter/fused_float8.h), whose bounds hold rounded once or twice, never the
# arithmetic the pictures are made of, so every build gives the same pictures bit for bit. ON by
# default when the building machine has both; such a build refuses, with a message, to run on a
# CPU without them (core/cpu_guard.cpp). OFF gives binaries for any x86-64 CPU, which pick their
# few AVX2 paths at run time (without FMA).
include(CheckCXXSourceRuns)
set(rt_avx2_default OFF)
if(NOT CMAKE_CROSSCOMPILING AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(CMAKE_REQUIRED_FLAGS "-mavx2 -mfma")
  check_cxx_source_runs(
    "int main() { return __builtin_cpu_supports(\"avx2\") && __builtin_cpu_supports(\"fma\") ? 0 : 1; }"
    RT_BUILD_MACHINE_HAS_AVX2_FMA)
  unset(CMAKE_REQUIRED_FLAGS)
  if(RT_BUILD_MACHINE_HAS_AVX2_FMA)
    set(rt_avx2_default ON)
  endif()
endif()
# No contraction either, whatever the target: GCC fuses a * b + c into one multiply-add wherever
# the code is compiled for a CPU that has one, and an AVX-512 target has one even without -mfma
# (as `-march=native` on a recent CPU, or a function's target attribute, would). Fused in one
# place and not in another, the same expression rounds differently: the plane's question before
# the exact test (lane_exact_hit.h) would no longer stand for the exact test's own arithmetic.
# tests/integration/fused_multiply_add_test.cpp checks the programs for double-precision ones.
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-ffp-contract=off)
endif()
option(RT_AVX2 "Compile for x86-64 CPUs with AVX2 and FMA (default: ON if this machine has them)"
       ${rt_avx2_default})
if(RT_AVX2)
  add_compile_options(-mavx2 -mfma)
  add_compile_definitions(RT_BUILT_FOR_AVX2)
endif()
