# `cmake --install`: the layers' static libraries, their public headers, the catplan command and
# a CMake package, so that another project can write
#
#   find_package(catplan 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE catplan::catplan)      # every layer
#   target_link_libraries(app PRIVATE catplan::transfer)     # or only a layer and those below it
#
# The layers are installed as they are built, one static library each (catplan::base ...
# catplan::report) with their link edges, rather than merged into one archive: a consumer links
# only the layers it uses, the exported targets keep the one-way layering of
# docs/architecture.md, and nothing is compiled twice. catplan::catplan links them all.
# The command line's own library (cli) is not part of the package.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CATPLAN_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/catplan)

get_property(catplan_layers GLOBAL PROPERTY CATPLAN_LAYERS)
list(REMOVE_ITEM catplan_layers cli)
set(catplan_layer_targets "")
# What the package must find again for the imported targets the layers link (publicly, or
# privately, which a static library still needs at link time): a table, so that a new one is
# an error here rather than a package that fails in a consumer.
set(CATPLAN_FIND_fmt::fmt "find_dependency(fmt)")
set(CATPLAN_FIND_nlohmann_json::nlohmann_json "find_dependency(nlohmann_json)")
set(CATPLAN_FIND_DEPENDENCIES "")
foreach(layer ${catplan_layers})
    list(APPEND catplan_layer_targets catplan_${layer})
    get_target_property(links catplan_${layer} LINK_LIBRARIES)
    foreach(lib ${links})
        if(lib MATCHES "^catplan::" OR NOT lib MATCHES "::")
            continue()
        endif()
        if(NOT DEFINED CATPLAN_FIND_${lib})
            message(FATAL_ERROR "layer ${layer} links ${lib}: say in ${CMAKE_CURRENT_LIST_FILE} "
                "how catplanConfig.cmake finds it")
        endif()
        string(FIND "${CATPLAN_FIND_DEPENDENCIES}" "${CATPLAN_FIND_${lib}}" at)
        if(at EQUAL -1)
            string(APPEND CATPLAN_FIND_DEPENDENCIES "${CATPLAN_FIND_${lib}}\n")
        endif()
    endforeach()
endforeach()

add_library(catplan_all INTERFACE)
add_library(catplan::catplan ALIAS catplan_all)
set_target_properties(catplan_all PROPERTIES EXPORT_NAME catplan)
target_link_libraries(catplan_all INTERFACE ${catplan_layer_targets})

install(TARGETS ${catplan_layer_targets} catplan_all EXPORT catplanTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET catplan)
    install(TARGETS catplan RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# The public headers: every layer's top-level headers (detail/ is private to its layer, the
# command line's headers are not an API).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/catplan
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    FILES_MATCHING PATTERN "*.hpp"
    PATTERN "detail" EXCLUDE
    PATTERN "cli" EXCLUDE)

install(EXPORT catplanTargets NAMESPACE catplan:: DESTINATION ${CATPLAN_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/catplanConfig.cmake.in
    ${PROJECT_BINARY_DIR}/catplanConfig.cmake
    INSTALL_DESTINATION ${CATPLAN_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/catplanConfigVersion.cmake
    VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/catplanConfig.cmake
    ${PROJECT_BINARY_DIR}/catplanConfigVersion.cmake
    DESTINATION ${CATPLAN_INSTALL_CMAKEDIR})
