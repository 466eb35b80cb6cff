# Helpers that make one target per layer, like mCRL2's mcrl2_add_library.

function(sfcv_apply_flags target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual
                                           -Wconversion -Wsign-conversion -Wno-sign-conversion
                                           -Wno-conversion)
  # GCC 12 reports false -Wrestrict positives inside std::string concatenation at -O2
  # (GCC bug 105329); they are not about our code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(SFCV_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(SFCV_SANITIZE)
    # Under the sanitizers GCC 12 reports -Wmaybe-uninitialized inside <regex> and other standard
    # headers (false positives that the plain build does not show).
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined
                                             -Wno-maybe-uninitialized)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(SFCV_FUZZ)
    # Coverage instrumentation for libFuzzer in every library; the harnesses link the driver.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined
                                             -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# SFCV_UNITY_BUILD: the whole target in one unity file (batch size 0). The files of a layer may
# not reuse a file-local name (an anonymous-namespace Parser, a static helper), which .ci/run's
# demo build checks.
function(sfcv_unity_build target)
  if(SFCV_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
  endif()
endfunction()

# sfcv_add_library(<name> <dir> [DEPS ...]): every .cpp below <dir> (not below a nested layer
# that has its own library) becomes part of sfcv_<name>; headers are included as "<layer>/x.hpp"
# relative to src/.
function(sfcv_add_library name dir)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  # For the internal-header fence (cmake/CheckInternalHeaders.cmake): which folder is a library.
  set_property(GLOBAL APPEND PROPERTY SFCV_LIBRARY_DIRS ${dir})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${dir}/*.cpp)
  if(sources)
    add_library(sfcv_${name} STATIC ${sources})
    target_include_directories(sfcv_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/src)
    target_link_libraries(sfcv_${name} PUBLIC ${ARG_DEPS})
  else()
    add_library(sfcv_${name} INTERFACE)
    target_include_directories(sfcv_${name} INTERFACE ${CMAKE_CURRENT_SOURCE_DIR}/src)
    target_link_libraries(sfcv_${name} INTERFACE ${ARG_DEPS})
  endif()
  if(sources)
    sfcv_apply_flags(sfcv_${name})
    sfcv_unity_build(sfcv_${name})
  endif()
endfunction()

# sfcv_add_unit_tests(<layer> <dir>): one GoogleTest executable per layer from <dir>/*_test.cpp.
function(sfcv_add_unit_tests layer dir)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  add_executable(test_${layer} ${sources})
  target_include_directories(test_${layer} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(test_${layer} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  target_compile_definitions(test_${layer} PRIVATE
      SFCV_SOURCE_DIR="${PROJECT_SOURCE_DIR}" SFCV_BINARY="$<TARGET_FILE:sfcv>"
      SFCV_GEN="$<TARGET_FILE:sfcv-gen>" SFCV_VERSION="${PROJECT_VERSION}")
  sfcv_apply_flags(test_${layer})
  add_dependencies(test_${layer} sfcv sfcv-gen)
  # Labels: `ctest -L unit` is the quick loop (the libraries on in-memory inputs); `e2e` runs the
  # binary on files.
  if(layer STREQUAL "e2e")
    set(kind e2e)
  else()
    set(kind unit)
  endif()
  gtest_discover_tests(test_${layer} DISCOVERY_TIMEOUT 60
                       PROPERTIES TIMEOUT 600 LABELS "${kind};${layer}")
endfunction()

# sfcv_add_header_check(<target> <dir> DEPS ...): every header below <dir> compiled on its own,
# one generated .cpp holding only `#include "<header>"` each (like mCRL2's headertest), so that a
# header that forgets one of its own includes fails the build.
function(sfcv_add_header_check target dir)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/${dir}
       ${CMAKE_CURRENT_SOURCE_DIR}/${dir}/*.hpp)
  set(sources "")
  foreach(h IN LISTS headers)
    string(MAKE_C_IDENTIFIER "${h}" id)
    set(out ${CMAKE_CURRENT_BINARY_DIR}/header_check/${id}.cpp)
    file(CONFIGURE OUTPUT ${out} CONTENT "#include \"${h}\"\n" @ONLY)
    list(APPEND sources ${out})
  endforeach()
  add_library(${target} OBJECT ${sources})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS})
  sfcv_apply_flags(${target})
endfunction()
