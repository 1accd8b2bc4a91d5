# catplan_add_layer(NAME SOURCES ... DEPENDS ... TESTS ...)
# One static library per layer (catplan_<NAME>, alias catplan::<NAME>, exported as catplan::<NAME>
# by `cmake --install`) with the rooted include dir src/, and one test binary per layer
# (catplan_<NAME>_tests) when TESTS are given. The code is position-independent so that the
# installed libraries also link into shared objects (the Python module, a ROS 2 plugin).
function(catplan_add_layer name)
    cmake_parse_arguments(L "" "" "SOURCES;DEPENDS;TESTS" ${ARGN})
    add_library(catplan_${name} STATIC ${L_SOURCES})
    add_library(catplan::${name} ALIAS catplan_${name})
    target_include_directories(catplan_${name} PUBLIC
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src> $<INSTALL_INTERFACE:include>)
    target_link_libraries(catplan_${name} PUBLIC ${L_DEPENDS})
    target_compile_options(catplan_${name} PRIVATE ${CATPLAN_WARNINGS})
    set_target_properties(catplan_${name} PROPERTIES
        EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
    set_property(GLOBAL APPEND PROPERTY CATPLAN_LAYERS ${name})
    if(CATPLAN_BUILD_TESTS AND L_TESTS)
        add_executable(catplan_${name}_tests ${L_TESTS})
        target_link_libraries(catplan_${name}_tests PRIVATE catplan_${name} GTest::gtest_main)
        target_compile_options(catplan_${name}_tests PRIVATE ${CATPLAN_WARNINGS})
        target_compile_definitions(catplan_${name}_tests
            PRIVATE CATPLAN_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
        gtest_discover_tests(catplan_${name}_tests DISCOVERY_TIMEOUT 60)
    endif()
endfunction()
