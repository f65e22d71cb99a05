# Proves that what sits in a layer's detail/ folder (the executor, the tiler's internals, the
# memory models) is reached only from inside that layer: no other source under src/ or apps/
# includes "<layer>/detail/...". Tests and benchmarks may, to test and time the internals.
# Run by ctest: cmake -DSOURCE_DIR=<repo> -P check_detail_includes.cmake
file(GLOB_RECURSE sources "${SOURCE_DIR}/src/*.h" "${SOURCE_DIR}/src/*.cpp" "${SOURCE_DIR}/apps/*.h"
     "${SOURCE_DIR}/apps/*.cpp")
set(violations "")
set(detail_includes 0)
foreach(source IN LISTS sources)
  file(STRINGS "${source}" includes REGEX "^#include \"[a-z_]+/detail/")
  file(RELATIVE_PATH relative "${SOURCE_DIR}" "${source}")
  foreach(line IN LISTS includes)
    math(EXPR detail_includes "${detail_includes} + 1")
    string(REGEX REPLACE "^#include \"([a-z_]+)/detail/.*" "\\1" layer_folder "${line}")
    if(NOT relative MATCHES "^src/${layer_folder}/")
      string(APPEND violations "  ${relative}: ${line}\n")
    endif()
  endforeach()
endforeach()
if(detail_includes EQUAL 0)
  message(FATAL_ERROR "no detail/ include found at all: is SOURCE_DIR (${SOURCE_DIR}) right?")
endif()
if(violations)
  message(FATAL_ERROR "detail/ headers included from outside their layer:\n${violations}")
endif()
message(STATUS "${detail_includes} detail/ includes, all inside their own layer")
