# Fences the libraries' internal headers: a header under a `detail/` folder, or one that says
# "Internal header of sfcv_<lib>" near its top, may only be included by files of its own
# library (the deepest library folder that holds it). Everything else (other libraries, the
# CLI, tests, benchmarks, fuzz harnesses) uses the public headers only.
#
#   cmake -DROOT=<dir> -DLIBRARY_DIRS=<src/a,src/b,...> -DSCAN_DIRS=<src,tests,...>
#         [-DEXCLUDE=<tests/data>] -P CheckInternalHeaders.cmake
#
# Include paths are relative to ROOT/src, as in the build ("semantics/detail/x.hpp"). Fails,
# naming every offending #include, when the fence is crossed.
cmake_minimum_required(VERSION 3.25)
foreach(var ROOT LIBRARY_DIRS SCAN_DIRS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CheckInternalHeaders: -D${var}=... is required")
  endif()
endforeach()

# Lists may be given with commas (ctest's COMMAND splits semicolons).
foreach(var LIBRARY_DIRS SCAN_DIRS EXCLUDE)
  string(REPLACE "," ";" ${var} "${${var}}")
endforeach()

# The library (a folder of LIBRARY_DIRS, relative to ROOT) a file belongs to, or "" for none.
function(owning_library path out)
  set(best "")
  foreach(lib IN LISTS LIBRARY_DIRS)
    string(LENGTH "${lib}" len)
    string(LENGTH "${best}" best_len)
    string(FIND "${path}" "${lib}/" at)
    if(at EQUAL 0 AND len GREATER best_len)
      set(best "${lib}")
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

# Internal headers: path relative to src/ -> owning library.
file(GLOB_RECURSE headers RELATIVE "${ROOT}" "${ROOT}/src/*.hpp")
set(internal "")
foreach(h IN LISTS headers)
  set(is_internal FALSE)
  if(h MATCHES "/detail/")
    set(is_internal TRUE)
  else()
    file(STRINGS "${ROOT}/${h}" mark LIMIT_INPUT 4096 REGEX "Internal header of sfcv_")
    if(mark)
      set(is_internal TRUE)
    endif()
  endif()
  if(is_internal)
    string(REGEX REPLACE "/detail/.*" "/x" probe "${h}")
    owning_library("${probe}" lib)
    string(REGEX REPLACE "^src/" "" key "${h}")
    list(APPEND internal "${key}")
    set(owner_${key} "${lib}")
  endif()
endforeach()

set(violations "")
set(checked 0)
foreach(dir IN LISTS SCAN_DIRS)
  file(GLOB_RECURSE files RELATIVE "${ROOT}" "${ROOT}/${dir}/*.cpp" "${ROOT}/${dir}/*.hpp")
  foreach(f IN LISTS files)
    set(skip FALSE)
    foreach(ex IN LISTS EXCLUDE)
      string(FIND "${f}" "${ex}/" at)
      if(at EQUAL 0)
        set(skip TRUE)
      endif()
    endforeach()
    if(skip)
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    owning_library("${f}" own)
    file(STRINGS "${ROOT}/${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*" "\\1" inc "${line}")
      if(inc IN_LIST internal AND NOT own STREQUAL owner_${inc})
        list(APPEND violations "${f} includes \"${inc}\", internal to ${owner_${inc}}")
      endif()
    endforeach()
  endforeach()
endforeach()

list(LENGTH internal n_internal)
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "internal headers included from outside their library:\n  ${text}")
endif()
message(STATUS "internal headers fenced: ${n_internal} internal headers, ${checked} files checked")
