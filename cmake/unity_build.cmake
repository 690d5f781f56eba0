# Unity builds (ROLLCHECK_UNITY, on by default): CMake compiles a target's
# C++ files in batches, each batch one translation unit that includes them.
# Our files are short (half are under 100 lines) and almost all of their
# compile time goes to the headers they include (the standard library,
# nlohmann/json, fmt/spdlog, Eigen, CLI11, DOLFINx/PETSc), so a batch parses
# those once instead of once per file. scripts/bench/bench_build.sh measures
# a clean build against the one before (docs/guide/architecture.md#the-build).
#
# A batch is one translation unit: two files that define the same name with
# internal linkage (an anonymous-namespace helper, a namespace-scope
# constexpr) cannot share one. Such a file is named in SEPARATE and compiled
# alone; a new clash shows as a redefinition error naming both files.
option(ROLLCHECK_UNITY "Compile each library's files in batches (unity build)" ON)
set(ROLLCHECK_UNITY_BATCH 16 CACHE STRING "Files per unity batch of the libraries and executables")
# The test executables' batches (cmake/test_executables.cmake), kept apart:
# test files define more names of their own (constants, helpers).
set(ROLLCHECK_TEST_UNITY_BATCH 16 CACHE STRING "Files per unity batch of the test executables")

# rollcheck_unity(TARGET [SEPARATE FILE...]): TARGET's C++ files in batches,
# but the FILEs (paths relative to the calling folder) alone.
function(rollcheck_unity target)
  if(NOT ROLLCHECK_UNITY)
    return()
  endif()
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SEPARATE")
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${ROLLCHECK_UNITY_BATCH})
  foreach(file ${arg_SEPARATE})
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${file})
      message(FATAL_ERROR "rollcheck_unity(${target}): no file ${file} to keep separate")
    endif()
  endforeach()
  list(TRANSFORM arg_SEPARATE PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/)
  if(arg_SEPARATE)
    set_source_files_properties(${arg_SEPARATE} TARGET_DIRECTORY ${target}
                                PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  endif()
endfunction()
