# Writes core's Version.cpp with the version string shown by --version and
# the About box: the project version plus `git describe` of the checkout, or
# the project version alone when the source is not a git checkout (e.g. a
# release tarball). Runs as a script at every build (core/CMakeLists.txt),
# so a new commit shows without reconfiguring; the file is rewritten only
# when the string changes, so an unchanged version recompiles nothing.
#
# cmake -DSOURCE_DIR=… -DPROJECT_VERSION=… -DINPUT=Version.cpp.in -DOUTPUT=Version.cpp -P BuildVersion.cmake
set(TACTISCOPE_VERSION_STRING "${PROJECT_VERSION}")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(
    COMMAND "${GIT_EXECUTABLE}" describe --tags --always --dirty
    WORKING_DIRECTORY "${SOURCE_DIR}"
    OUTPUT_VARIABLE git_describe
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET
    RESULT_VARIABLE git_result)
  if(git_result EQUAL 0 AND git_describe)
    set(TACTISCOPE_VERSION_STRING "${PROJECT_VERSION}+${git_describe}")
  endif()
endif()
configure_file("${INPUT}" "${OUTPUT}" @ONLY)
