# Writes OUT: the commit `rollcheck --version` prints, `git describe --always
# --dirty` of SOURCE ("unknown" outside a git checkout, or without GIT).
# Run at every build (CMakeLists.txt, rollcheck_commit_stamp), so that the
# stamp follows each commit without a new configure; the file is rewritten
# only when the commit changes, so that only what prints it is rebuilt.
#   cmake -DGIT=/usr/bin/git -DSOURCE=DIR -DOUT=FILE -P cmake/commit_stamp.cmake
set(commit "")
if(GIT)
  execute_process(COMMAND ${GIT} -C ${SOURCE} describe --always --dirty
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
endif()
if(NOT commit)
  set(commit unknown)
endif()
file(CONFIGURE OUTPUT ${OUT} CONTENT "#pragma once\n#define ROLLCHECK_GIT_COMMIT \"${commit}\"\n")
