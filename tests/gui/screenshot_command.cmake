# The `floorcover --screenshot FILE.png [PLAN]` command end to end: a PNG for a good plan,
# exit code 2 and a message naming the file for a broken one.
file(REMOVE ${OUT})
execute_process(COMMAND ${FLOORCOVER} --screenshot ${OUT} ${PLAN} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "floorcover --screenshot exited with ${rc}")
endif()
file(SIZE ${OUT} size)
file(READ ${OUT} magic LIMIT 4 HEX)
if(size LESS 20000 OR NOT magic STREQUAL "89504e47")
  message(FATAL_ERROR "${OUT} is not a plausible PNG (${size} bytes, starts ${magic})")
endif()
execute_process(COMMAND ${FLOORCOVER} --screenshot ${OUT}.bad.png ${BROKEN}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "selfintersecting.geojson")
  message(FATAL_ERROR "a broken plan gave exit ${rc} and: ${err}")
endif()
message(STATUS "screenshot: ${size} bytes; broken plan refused: ${err}")
