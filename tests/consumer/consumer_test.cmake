# The planner core built alone (GUI, Torch and importers off), installed with its CMake
# package, and a separate project (tests/consumer) built and run against that installation.
# -DSOURCE=<project root> -DWORK=<scratch folder> -DGENERATOR=<cmake generator>
file(REMOVE_RECURSE ${WORK})
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${step}: ok")
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run("configure the core alone" ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/core -G ${GENERATOR}
    -DFLOORCOVER_GUI=OFF -DFLOORCOVER_TORCH=OFF -DFLOORCOVER_IMPORTERS=OFF
    -DFC_BUILD_TESTS=OFF -DFC_BUILD_BENCH=OFF -DCMAKE_INSTALL_PREFIX=${WORK}/prefix
    # no optimisation or debug information: the build is the test, and it compiles faster
    -DCMAKE_BUILD_TYPE=None)
# Nothing but the core may be configured: no Qt, LibTorch, GDAL or assimp was looked for.
file(READ ${WORK}/core/CMakeCache.txt cache)
foreach(package Qt6 Torch GDAL assimp QCustomPlotQt6)
  if(cache MATCHES "\n${package}_DIR:PATH=/")
    message(FATAL_ERROR "the core-only build looked for and found ${package}")
  endif()
endforeach()
run("build the core" ${CMAKE_COMMAND} --build ${WORK}/core)
run("install the core" ${CMAKE_COMMAND} --install ${WORK}/core --component core)
run("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE}/tests/consumer -B ${WORK}/consumer
    -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${WORK}/prefix)
run("build the consumer" ${CMAKE_COMMAND} --build ${WORK}/consumer)
run("run the consumer" ${WORK}/consumer/plan_room)
message(STATUS "${last_output}")
