# One interface target carrying our warning flags; applied to our targets only.
add_library(rt_warnings INTERFACE)
target_compile_options(rt_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast)
if(RT_WERROR)
  target_compile_options(rt_warnings INTERFACE -Werror)
endif()
if(RT_FUZZ AND NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "RT_FUZZ needs Clang (libFuzzer), but the C++ compiler is "
                      "${CMAKE_CXX_COMPILER_ID}: configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
# RT_FUZZ runs its targets under the same checks: a sanitizer report is a finding.
if(RT_SANITIZE OR RT_FUZZ)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
if(RT_FUZZ)
  # Coverage for libFuzzer in the whole library; only the fuzz targets link libFuzzer itself
  # (-fsanitize=fuzzer, fuzz/CMakeLists.txt), so the other programs keep their main().
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
