# Derives the version string shown by --version and the About box from
# `git describe` at configure time, falling back to the project version when
# the source is not a git checkout (e.g. a release tarball).
find_package(Git QUIET)
set(TACTISCOPE_VERSION_STRING "${PROJECT_VERSION}")
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")
  execute_process(
    COMMAND "${GIT_EXECUTABLE}" describe --tags --always --dirty
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    OUTPUT_VARIABLE _tactiscope_git_describe
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET
    RESULT_VARIABLE _tactiscope_git_result)
  if(_tactiscope_git_result EQUAL 0 AND _tactiscope_git_describe)
    set(TACTISCOPE_VERSION_STRING "${PROJECT_VERSION}+${_tactiscope_git_describe}")
  endif()
endif()
