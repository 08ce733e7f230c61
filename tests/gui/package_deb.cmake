# The Debian package: cpack builds it from the build tree, and it holds both programs, the
# desktop entry and the icon, with Qt among its dependencies.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CPACK} --config ${BUILD}/CPackConfig.cmake -G DEB -B ${WORK}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cpack failed (${rc}): ${out} ${err}")
endif()
file(GLOB debs ${WORK}/floorcover_*.deb)
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one .deb in ${WORK}, found: ${debs}")
endif()
execute_process(COMMAND dpkg-deb --contents ${debs} OUTPUT_VARIABLE contents)
execute_process(COMMAND dpkg-deb --field ${debs} Depends OUTPUT_VARIABLE depends)
foreach(path ./usr/bin/floorcover ./usr/bin/floorcover-cli
        ./usr/share/applications/floorcover.desktop
        ./usr/share/icons/hicolor/scalable/apps/floorcover.svg
        ./usr/share/metainfo/invalid.example.FloorCover.metainfo.xml)
  string(FIND "${contents}" "${path}\n" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "${path} is missing from the package:\n${contents}")
  endif()
endforeach()
# The core's development files (headers, static library) are not for end users.
string(FIND "${contents}" "include/floorcover" dev)
if(NOT dev EQUAL -1)
  message(FATAL_ERROR "the package holds the core's development files:\n${contents}")
endif()
if(NOT depends MATCHES "libqt6widgets6")
  message(FATAL_ERROR "the package does not depend on Qt: ${depends}")
endif()
message(STATUS "package: ${debs}; depends: ${depends}")
