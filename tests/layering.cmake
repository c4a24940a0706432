# The include arrows of docs/architecture.md ("Layers"), checked on the source tree:
#   include/simdphys (public) -> src/ -> simd/ -> core/ and the Eigen-free public headers;
#   tests/ and bench/ reach internals only through testing/.
# Run as: cmake -DROOT=<source dir> -P layering.cmake. Prints every broken arrow and fails.
cmake_minimum_required(VERSION 3.25)

# Public headers the kernels may include: plain types and constants, no Eigen (checked below).
set(eigen_free core.hpp stream_fields.hpp bvh_types.hpp detail/float_math.hpp)

set(broken "")
macro(check_files glob_dir pattern why)
  file(GLOB_RECURSE files "${ROOT}/${glob_dir}/*.hpp" "${ROOT}/${glob_dir}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(line MATCHES "${pattern}")
        file(RELATIVE_PATH rel "${ROOT}" "${f}")
        string(STRIP "${line}" line)
        list(APPEND broken "${rel}: ${line}  (${why})")
      endif()
    endforeach()
  endforeach()
endmacro()

# simd/ and core/: nothing from src/, testing/ or Eigen; of the public headers only the Eigen-free.
string(REPLACE ";" "|" allowed "${eigen_free}")
string(REPLACE "." "\\." allowed "${allowed}")
foreach(dir simd core)
  check_files(${dir} "[\"<](src/|\\.\\./|testing/|Eigen)" "${dir}/ depends only on core/")
  check_files(${dir} "\"simdphys/" "" )
endforeach()
# The second pass above listed every public include; keep only those outside the Eigen-free set.
set(kept "")
foreach(b IN LISTS broken)
  if(b MATCHES "\"simdphys/" AND b MATCHES "\"simdphys/(${allowed})\"")
    continue()
  endif()
  string(REPLACE "  ()" "  (the kernels see only the Eigen-free public headers)" b "${b}")
  list(APPEND kept "${b}")
endforeach()
set(broken "${kept}")

# core/ knows nothing of simd/ either: both the reference and the targets include it.
check_files(core "\"simd/" "core/ sits below simd/")
# The Eigen-free public headers stay Eigen-free, so the kernels can include them.
foreach(h IN LISTS eigen_free)
  file(STRINGS "${ROOT}/include/simdphys/${h}" lines REGEX "^[ \t]*#[ \t]*include")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "<[a-z_]+>" AND NOT line MATCHES "\"simdphys/(${allowed})\"")
      list(APPEND broken "include/simdphys/${h}: ${line}  (an Eigen-free header includes only the standard library and its own set)")
    endif()
  endforeach()
endforeach()
# Public headers are installed alone: nothing from the tree's private folders.
check_files(include "\"(src|simd|core|testing)/" "public headers are installed alone")
# Tests and benchmarks use the public API, or the explicit test-support headers of testing/.
check_files(tests "\"(src|simd|core)/|\\.\\./(src|simd|core)/" "tests reach internals only through testing/")
check_files(bench "\"(src|simd|core)/|\\.\\./(src|simd|core)/" "benchmarks reach internals only through testing/")

# No public header names a benchmark or a baseline kept for one.
file(GLOB_RECURSE public "${ROOT}/include/*.hpp")
foreach(f IN LISTS public)
  file(STRINGS "${f}" lines REGEX "Autovec|[Bb]enchmark")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH rel "${ROOT}" "${f}")
    list(APPEND broken "${rel}: ${line}  (no public header names a benchmark)")
  endforeach()
endforeach()

list(LENGTH broken n)
if(n GREATER 0)
  list(JOIN broken "\n  " text)
  message(FATAL_ERROR "layering: ${n} broken arrow(s):\n  ${text}")
endif()
message(STATUS "layering: every include follows the arrows")
