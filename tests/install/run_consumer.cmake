# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DGENERATOR=... -DCXX_COMPILER=...
#       -DCXX_LAUNCHER=... -DCXX_FLAGS=... -DBUILD_TYPE=...] -P run_consumer.cmake
# Installs the build tree into WORK_DIR/prefix, checks that every installed header's catplan
# includes are installed too, then configures, builds and runs tests/install/consumer against it.

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
    endif()
    set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

foreach(f catplanConfig.cmake catplanConfigVersion.cmake catplanTargets.cmake)
    if(NOT EXISTS ${prefix}/lib/cmake/catplan/${f})
        message(FATAL_ERROR "not installed: lib/cmake/catplan/${f}")
    endif()
endforeach()
if(NOT EXISTS ${prefix}/bin/catplan)
    message(FATAL_ERROR "not installed: bin/catplan")
endif()

# A header that includes one that was not installed (a detail/ header, say) would only fail in
# a consumer that happens to include it: check them all.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/catplan/*.hpp)
list(LENGTH headers nheaders)
if(nheaders LESS 20)
    message(FATAL_ERROR "only ${nheaders} headers installed")
endif()
foreach(h ${headers})
    file(STRINGS ${prefix}/include/${h} includes REGEX "^#include \"catplan/")
    foreach(line ${includes})
        string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" inc "${line}")
        if(NOT EXISTS ${prefix}/include/${inc})
            message(FATAL_ERROR "${h} includes ${inc}, which is not installed")
        endif()
    endforeach()
endforeach()

set(args -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(GENERATOR)
    list(APPEND args -G ${GENERATOR})
endif()
foreach(var CXX_COMPILER CXX_FLAGS BUILD_TYPE)
    if(${var})
        list(APPEND args "-DCMAKE_${var}=${${var}}")
    endif()
endforeach()
if(CXX_LAUNCHER)
    list(APPEND args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run(${CMAKE_COMMAND} ${args})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer ${SOURCE_DIR}/examples/colorblocks_to_kitchen/appendix_map.cp
    ${SOURCE_DIR}/examples/colorblocksworld/paper.plan)
message("${last_output}")
file(REMOVE_RECURSE ${WORK_DIR})
