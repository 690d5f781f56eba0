# Precompiled headers (ROLLCHECK_PCH, on by default): the third-party
# headers that most translation units parse (the standard library, fmt,
# spdlog, nlohmann/json, Eigen; in the FEM libraries DOLFINx, PETSc and MPI;
# in the tests GoogleTest) are parsed once instead of once per file.
# The tests, one file and one executable each, share one of two headers
# (those that link the fem layer, with its flags, and those that do not),
# built by a stub target with the tests' flags. A library gets its own only without unity
# batches (cmake/unity_build.cmake): with them it has a few translation
# units, so a header of its own has little to save.
# scripts/bench/bench_build.sh measures a clean build.
#
# ccache caches compilations that use a precompiled header only with
# sloppiness pch_defines and time_macros; the compiler launcher sets them.
option(ROLLCHECK_PCH "Precompile the common third-party headers" ON)

set(rollcheck_pch_light
    <algorithm> <array> <chrono> <cmath> <filesystem> <fstream> <functional> <limits> <map> <memory> <numbers>
    <optional> <span> <string> <vector> <fmt/format.h> <spdlog/spdlog.h> <nlohmann/json.hpp>)
set(rollcheck_pch_eigen <Eigen/Core> <Eigen/Geometry>)
set(rollcheck_pch_fem
    <mpi.h> <petscksp.h> <dolfinx/common/IndexMap.h> <dolfinx/fem/Constant.h> <dolfinx/fem/DirichletBC.h>
    <dolfinx/fem/Form.h> <dolfinx/fem/Function.h> <dolfinx/fem/FunctionSpace.h> <dolfinx/fem/assembler.h>
    <dolfinx/fem/utils.h> <dolfinx/la/Vector.h> <dolfinx/mesh/Mesh.h> <dolfinx/mesh/MeshTags.h>
    <dolfinx/mesh/utils.h>)

# The launcher with the sloppiness ccache needs to cache compilations with a PCH.
function(rollcheck_pch_launcher ccache)
  if(ROLLCHECK_PCH AND ccache)
    set(launcher ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=pch_defines,time_macros ${ccache})
    set(CMAKE_C_COMPILER_LAUNCHER ${launcher} PARENT_SCOPE)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher} PARENT_SCOPE)
  endif()
endfunction()

# TARGET's C++ files precompile the header groups named after it (light,
# eigen, fem); C files (the generated forms) are left alone.
function(rollcheck_precompile target)
  if(NOT ROLLCHECK_PCH)
    return()
  endif()
  set(headers)
  foreach(group ${ARGN})
    list(APPEND headers ${rollcheck_pch_${group}})
  endforeach()
  list(TRANSFORM headers REPLACE "^<(.+)>$" "$<$<COMPILE_LANGUAGE:CXX>:<\\1$<ANGLE-R>>")
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# The tests' two shared headers: stub targets compiled with the tests' flags
# (tests/CMakeLists.txt), from which each test reuses one.
function(rollcheck_test_pch_stubs)
  if(NOT ROLLCHECK_PCH)
    return()
  endif()
  set(stub ${CMAKE_BINARY_DIR}/rollcheck_pch_stub.cpp)
  # Written only when its text changes: a rewrite would rebuild the stubs at every configure.
  file(CONFIGURE OUTPUT ${stub} CONTENT "// Stub: the tests' precompiled header is built with this file.\n")
  foreach(kind light fem)
    add_library(rollcheck_test_pch_${kind} OBJECT ${stub})
    target_compile_options(rollcheck_test_pch_${kind} PRIVATE ${ARGN})
    if(kind STREQUAL fem)
      # Without DOLFINx: its common/Scatterer.h says `using namespace dolfinx`
      # at global scope, so in a test that says `using namespace rollcheck`
      # and includes no DOLFINx header `fem::` would become ambiguous.
      target_link_libraries(rollcheck_test_pch_${kind} PRIVATE rollcheck_fem GTest::gtest)
      rollcheck_precompile(rollcheck_test_pch_${kind} light eigen)
    else()
      target_link_libraries(rollcheck_test_pch_${kind} PRIVATE rollcheck_geometry GTest::gtest)
      rollcheck_precompile(rollcheck_test_pch_${kind} light eigen)
    endif()
    target_precompile_headers(rollcheck_test_pch_${kind} PRIVATE <gtest/gtest.h>)
  endforeach()
endfunction()

# Whether TARGET is rollcheck_fem or links it, directly or through the
# libraries it links (their flags, DOLFINx's among them, reach the test).
function(rollcheck_links_fem out target)
  set(${out} FALSE PARENT_SCOPE)
  if(target STREQUAL "rollcheck_fem")
    set(${out} TRUE PARENT_SCOPE)
    return()
  endif()
  if(NOT TARGET ${target})
    return()
  endif()
  get_target_property(linked ${target} INTERFACE_LINK_LIBRARIES)
  foreach(library ${linked})
    if(library MATCHES "^rollcheck_")
      rollcheck_links_fem(links ${library})
      if(links)
        set(${out} TRUE PARENT_SCOPE)
        return()
      endif()
    endif()
  endforeach()
endfunction()

# TEST reuses the stub's header of its kind: fem if it links the FEM library.
# A test given the other kind's header would not use it (different flags:
# -Winvalid-pch says so in the build log) and parse every header itself.
function(rollcheck_test_pch test)
  if(NOT ROLLCHECK_PCH)
    return()
  endif()
  set(kind light)
  foreach(layer ${ARGN})
    rollcheck_links_fem(links ${layer})
    if(links)
      set(kind fem)
    endif()
  endforeach()
  if(NOT ARGN OR ARGN STREQUAL "rollcheck_core")
    return() # without Eigen's include path the header could not be parsed again
  endif()
  target_precompile_headers(${test} REUSE_FROM rollcheck_test_pch_${kind})
endfunction()
