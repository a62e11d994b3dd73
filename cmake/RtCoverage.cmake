# RT_COVERAGE: every target compiled and linked with GCC's --coverage, so each run of a test or a
# program adds its line counts to the .gcda files beside the objects (scripts/coverage reads them).
# -O1: GCC places the counters before it optimises, so the lines counted are the source's; the
# suite runs about five times faster than at -O0 and the module figures stay within 1.5 points.
if(RT_COVERAGE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "RT_COVERAGE needs GCC (gcov); the compiler is ${CMAKE_CXX_COMPILER_ID}")
  endif()
  # Atomic counters: the renderer's threads update the same counters at once.
  add_compile_options(--coverage -fprofile-update=atomic -O1)
  add_link_options(--coverage)
endif()
