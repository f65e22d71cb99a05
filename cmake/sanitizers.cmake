# Sanitizer and fuzzer builds (scripts/sanitize.sh, scripts/fuzz_smoke.sh; docs/robustness.md).
# ONTILE_SANITIZERS instruments every target (library, CLI, tests): "address,undefined" or
# "thread". ONTILE_BUILD_FUZZERS adds libFuzzer's coverage instrumentation and the fuzz/
# targets. Both need clang: GCC 12's -fsanitize=null reports a false "load of null pointer" on
# every `extern thread_local` access (40 reports in raster/texel_trace.h), clang 14 does not,
# and libFuzzer ships only with clang (Debian 12: libclang-rt-14-dev).
set(ONTILE_SANITIZERS "" CACHE STRING
    "Sanitizers for every target, e.g. address,undefined or thread (clang)")
option(ONTILE_BUILD_FUZZERS "Build the libFuzzer targets in fuzz/ (clang)" OFF)

if(ONTILE_SANITIZERS OR ONTILE_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ONTILE_SANITIZERS and ONTILE_BUILD_FUZZERS need clang "
                        "(cmake -DCMAKE_CXX_COMPILER=clang++); found ${CMAKE_CXX_COMPILER_ID}")
  endif()
endif()

if(ONTILE_SANITIZERS)
  # Frame pointers give the sanitizers' stack traces every frame; any finding ends the
  # process with an error (no "recover and continue") so a test or fuzz run cannot pass by luck.
  add_compile_options(-fsanitize=${ONTILE_SANITIZERS} -fno-omit-frame-pointer
                      -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${ONTILE_SANITIZERS})
endif()

if(ONTILE_BUILD_FUZZERS)
  # Coverage feedback for libFuzzer in every object; fuzz/CMakeLists.txt links the driver.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
