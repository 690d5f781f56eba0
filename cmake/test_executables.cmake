# The GoogleTest executables: one per folder of tests/ (a layer, or a wing
# under study/), not one per test file. A clean build spent more than half of
# its time on the tests, 83 executables each parsing GoogleTest and the
# project's headers, each linked against its layers and each started at
# build time to list its tests (gtest_discover_tests: 2-4 s apiece for one
# that links DOLFINx). One executable per folder links and lists once, and
# compiles its files in unity batches like the libraries
# (cmake/unity_build.cmake; a file that clashes in a batch is named SEPARATE).
#
# Each test keeps its CTest name (Suite.Test) and its label: the name of the
# file that defines it (tests/fem/test_slab_contact.cpp -> test_slab_contact),
# or `long`, plus the executable's name (tests_fem). The file of each test is
# read from its TEST(Suite, Name) / TEST_P(Suite, Name) line at configure
# time, and a script that CTest runs after the discovered tests' own
# (rollcheck_test_labels) sets the labels from that map.

# rollcheck_test_names(OUT FILTER SOURCE): the Suite.Name of every TEST and
# TEST_P in SOURCE, and the --gtest_filter of their tests (a parameterised
# test's are PREFIX/Suite.Name/VALUE). A test whose declaration this does not
# read would get no file and so no label: that is an error here, not a test
# quietly in the wrong suite.
function(rollcheck_test_names out filter source)
  file(STRINGS ${source} declared REGEX "^[ \t]*TEST(_P|_F)?[ \t]*\\(")
  set(names)
  set(patterns)
  foreach(line ${declared})
    if(NOT line MATCHES "^TEST(_P)?\\(([A-Za-z0-9_]+), ([A-Za-z0-9_]+)\\)")
      message(FATAL_ERROR "${source}: cannot read the test's name from `${line}` (one line, TEST(Suite, Name))")
    endif()
    set(name ${CMAKE_MATCH_2}.${CMAKE_MATCH_3})
    list(APPEND names ${name})
    if(CMAKE_MATCH_1)
      list(APPEND patterns */${name}/*)
    else()
      list(APPEND patterns ${name})
    endif()
  endforeach()
  list(JOIN patterns ":" patterns)
  set(${out} ${names} PARENT_SCOPE)
  set(${filter} ${patterns} PARENT_SCOPE)
endfunction()

# rollcheck_test_layers(OUT SOURCE): the libraries of every layer named in
# SOURCE's #include lines, so that the geometry tests do not pull in DOLFINx.
function(rollcheck_test_layers out source)
  file(STRINGS ${source} includes REGEX "^#include \"(core|geometry|oracle|contact|fem|study|io|audit)/")
  set(layers)
  foreach(line ${includes})
    # study/WING/x.h -> rollcheck_study_WING; LAYER/x.h (and fem/mesh, fem/scenes) -> rollcheck_LAYER
    if(line MATCHES "^#include \"study/([a-z_]+)/")
      list(APPEND layers rollcheck_study_${CMAKE_MATCH_1})
    else()
      string(REGEX REPLACE "^#include \"([a-z]+)/.*" "rollcheck_\\1" layer "${line}")
      list(APPEND layers ${layer})
    endif()
  endforeach()
  set(${out} ${layers} PARENT_SCOPE)
endfunction()

# rollcheck_test_executable(NAME SOURCES file... [SEPARATE file...]
#                           [LONG_TESTS name...] [LONG_CASES entry...] [TWO_RANKS name...])
# NAME is built from the SOURCES (absolute paths) and its tests registered.
# LONG_TESTS: files (test_NAME) whose tests are all `long` but for the
# suites named *Quick; LONG_CASES: test_NAME:Suite.Test entries that are
# `long`; TWO_RANKS: files whose tests run a second time on 2 ranks (one
# CTest test, test_NAME_2_ranks, filtered to that file's tests). SEPARATE:
# files (relative to tests/) kept out of the unity batches.
function(rollcheck_test_executable exe)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;SEPARATE;LONG_TESTS;LONG_CASES;TWO_RANKS")
  add_executable(${exe} ${arg_SOURCES})
  rollcheck_unity(${exe} SEPARATE ${arg_SEPARATE})
  if(ROLLCHECK_UNITY)
    set_target_properties(${exe} PROPERTIES UNITY_BUILD_BATCH_SIZE ${ROLLCHECK_TEST_UNITY_BATCH})
  endif()
  set(layers)
  set(map "# ${exe}: the file (test_NAME) of each test, written by cmake/test_executables.cmake\n")
  set(long_names)
  foreach(src ${arg_SOURCES})
    get_filename_component(file ${src} NAME_WE)
    rollcheck_test_layers(file_layers ${src})
    list(APPEND layers ${file_layers})
    rollcheck_test_names(names filter ${src})
    foreach(test ${names})
      if(DEFINED source_of_${test})
        message(FATAL_ERROR "${exe}: ${test} is defined in ${file} and in ${source_of_${test}}")
      endif()
      set(source_of_${test} ${file})
      string(APPEND map "set(rollcheck_file_${test} ${file})\n")
    endforeach()
    # A renamed test would match no entry and quietly rejoin the default suite.
    foreach(entry ${arg_LONG_CASES})
      if(entry MATCHES "^${file}:(.*)$")
        if(NOT CMAKE_MATCH_1 IN_LIST names)
          message(FATAL_ERROR "long_cases: ${entry} names no test in ${src}")
        endif()
        list(APPEND long_names ${CMAKE_MATCH_1})
      endif()
    endforeach()
    # build/tests/test_NAME, the commands the docs quote, runs this file's
    # tests (a --gtest_filter given to it replaces the file's filter).
    file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${file}
         CONTENT "#!/bin/sh\n# ${file}'s tests in ${exe}\nexec $<TARGET_FILE:${exe}> '--gtest_filter=${filter}' \"$@\"\n"
         FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
    if(file IN_LIST arg_TWO_RANKS)
      # Node pairs across processes: this file's tests again on 2 ranks.
      add_test(NAME ${file}_2_ranks COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 $<TARGET_FILE:${exe}>
                                            --gtest_filter=${filter})
      set(label ${file})
      if(file IN_LIST arg_LONG_TESTS)
        set(label long)
      endif()
      set_tests_properties(${file}_2_ranks PROPERTIES LABELS "${label};${exe}"
        ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OPENBLAS_NUM_THREADS=1")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES layers)
  target_link_libraries(${exe} PRIVATE ${layers} GTest::gtest_main)
  # The code under test is the layers' libraries, built as released (-O3);
  # the test drivers themselves compile at -O1, 20-30 % faster (measured:
  # test_geometry.cpp 9.3 s -> 6.6 s, test_rim_end_contact.cpp 4.7 -> 3.7 s).
  target_compile_options(${exe} PRIVATE -O1)
  rollcheck_test_pch(${exe} ${layers})
  target_include_directories(${exe} PRIVATE ${GMSH_INCLUDE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_definitions(${exe} PRIVATE
    ROLLCHECK_REFERENCE_MESH_DIR="${reference_mesh_dir}"
    ROLLCHECK_REFERENCE_DATA_DIR="${reference_data_dir}"
    ROLLCHECK_BINARY="$<TARGET_FILE:rollcheck>"
    ROLLCHECK_TEST_TMP="${CMAKE_BINARY_DIR}/test_tmp")
  gtest_discover_tests(${exe} DISCOVERY_TIMEOUT 60 TEST_LIST ${exe}_TESTS)
  set(labels_script ${CMAKE_CURRENT_BINARY_DIR}/${exe}_labels.cmake)
  string(APPEND map "set(rollcheck_long_tests ${arg_LONG_TESTS})\nset(rollcheck_long_cases ${long_names})\n"
                    "rollcheck_test_labels(${exe} \${${exe}_TESTS})\n")
  file(WRITE ${labels_script} "include(${ROLLCHECK_SOURCE_DIR}/cmake/test_labels.cmake)\n${map}")
  # After gtest_discover_tests' own script, which defines ${exe}_TESTS.
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${labels_script})
endfunction()
