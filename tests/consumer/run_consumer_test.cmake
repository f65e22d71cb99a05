# The installable package end to end (ctest: Package.ConsumerBuildsAgainstTheInstall): installs
# the build into a temporary prefix, configures and builds tests/consumer/ against it with
# find_package(ontile), runs it, and checks that its frame is the CLI's: the same bytes written
# and read (from `ontile render --report`) and the same image (`ontile compare`, bit for bit);
# then that the installed CLI's `golden` finds the installed demo scene and references.
# cmake -DBUILD_DIR=<build> -DCONSUMER_DIR=<tests/consumer> -DWORK=<scratch> -DCXX=<compiler>
#       [-DLAUNCHER=ccache] -P run_consumer_test.cmake
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(prefix ${WORK}/prefix)
run_step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed bin/ontile include/ontile/context/render_context.h include/ontile/pipelines/kit/render_frame.h
                  share/ontile/scenes/demo.glb lib/cmake/ontile/ontileConfig.cmake
                  lib/cmake/ontile/ontileConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "the install has no ${installed}")
  endif()
endforeach()

set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run_step("configuring the consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK}/build
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} ${launcher} -DCMAKE_PREFIX_PATH=${prefix})
run_step("building the consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
run_step("running the consumer" ${WORK}/build/render_demo ${WORK}/consumer.png)
set(consumer "${step_output}")
message(STATUS "consumer:\n${consumer}")
# The CLI as the package's imported target ontile::cli names it.
file(READ ${WORK}/build/ontile_cli_path.txt cli)
if(NOT cli STREQUAL "${prefix}/bin/ontile")
  message(FATAL_ERROR "ontile::cli is '${cli}', not ${prefix}/bin/ontile")
endif()

# The same frame through the installed CLI, which finds its demo scene in share/ontile itself.
run_step("ontile render" ${cli} render --scene ${prefix}/share/ontile/scenes/demo.glb
         --pipeline cartoon --size 320x180 --threads 2 --out ${WORK}/cli.png --report ${WORK}/cli.json)
file(READ ${WORK}/cli.json report)
foreach(key bytes_read bytes_written)
  string(JSON expected GET "${report}" frame ${key})
  if(NOT consumer MATCHES "${key}: ${expected}\n")
    message(FATAL_ERROR "the consumer's ${key} differs from the CLI's ${expected}:\n${consumer}")
  endif()
endforeach()
run_step("ontile compare" ${cli} compare ${WORK}/consumer.png ${WORK}/cli.png)
# The installed CLI finds its data beside itself (P/share/ontile): the built-in golden cases on the
# demo match the installed references (the shared-asset cases are skipped: not installed).
run_step("ontile golden (installed)" ${cli} golden --failures ${WORK}/golden_failures)
if(NOT step_output MATCHES "demo_cartoon +match")
  message(FATAL_ERROR "the installed golden run compared nothing:\n${step_output}")
endif()
message(STATUS "consumer frame identical to the CLI's (image and traffic)")
file(REMOVE_RECURSE ${WORK})
