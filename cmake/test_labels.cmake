# Run by CTest (cmake/test_executables.cmake includes it in each test
# executable's labels script): the labels of the tests that
# gtest_discover_tests found in EXE. A test's labels are the file that
# defines it (test_NAME, from rollcheck_file_Suite.Name) and EXE; a test of a
# long file (rollcheck_long_tests: but for its suites named *Quick) or a long
# case (rollcheck_long_cases: Suite.Name) has the one label `long`, which
# keeps it out of the default suite (`ctest -LE long`).
# (list(FIND), not IN_LIST: CTest reads this without the project's policies.)
function(rollcheck_test_labels exe)
  set(labels)
  foreach(test ${ARGN})
    # PREFIX/Suite.Name/VALUE (a parameterised test) -> Suite.Name
    string(REGEX REPLACE "^([^/]*/)?([^./]+\\.[^/]+)(/.*)?$" "\\2" key "${test}")
    set(file "${rollcheck_file_${key}}")
    list(FIND rollcheck_long_tests "${file}" long_file)
    list(FIND rollcheck_long_cases "${key}" long_case)
    if((NOT long_file EQUAL -1 AND NOT key MATCHES "Quick\\.") OR NOT long_case EQUAL -1)
      set(label long)
    elseif(file)
      set(label "${file};${exe}")
    else()
      set(label "${exe}")
    endif()
    string(MAKE_C_IDENTIFIER "${label}" group)
    list(APPEND tests_${group} "${test}")
    set(labels_${group} "${label}")
    list(APPEND groups ${group})
  endforeach()
  if(groups)
    list(REMOVE_DUPLICATES groups)
  endif()
  foreach(group ${groups})
    set_tests_properties(${tests_${group}} PROPERTIES LABELS "${labels_${group}}")
  endforeach()
endfunction()
