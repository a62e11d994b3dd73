# rt_add_module(NAME DEPS dep... [EXCLUDE regex]): a static library from every .cpp in
# src/rt/NAME, less those whose path matches EXCLUDE (an optional backend not being built).
function(rt_add_module name)
  cmake_parse_arguments(ARG "" "EXCLUDE" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  if(ARG_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX "${ARG_EXCLUDE}")
  endif()
  if(sources)
    add_library(rt_${name} STATIC ${sources})
    target_include_directories(rt_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(rt_${name} PUBLIC ${ARG_DEPS} PRIVATE rt_warnings)
  else()
    # A module with headers only (so far).
    add_library(rt_${name} INTERFACE)
    target_include_directories(rt_${name} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(rt_${name} INTERFACE ${ARG_DEPS})
  endif()
endfunction()

# rt_add_tests(NAME DEPS dep...): one GoogleTest binary from the *.cpp files in tests/NAME and its
# folders, which mirror src/rt/NAME's (every *_test.cpp, and the helpers beside them).
function(rt_add_tests name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(${name}_test ${sources})
  target_link_libraries(${name}_test PRIVATE ${ARG_DEPS} rt_test_support GTest::gtest_main rt_warnings)
  gtest_discover_tests(${name}_test
    PROPERTIES ENVIRONMENT "RT_SOURCE_DIR=${PROJECT_SOURCE_DIR};RT_BIN_DIR=${CMAKE_BINARY_DIR}/bin"
    DISCOVERY_TIMEOUT 60)
endfunction()
