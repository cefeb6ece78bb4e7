# Writes OUTPUT (a C++ source) with the commit the build's sources are at and whether tracked files
# differ from it, so that every run.json and run.log names the code that produced it (a referee
# reruns a published case with that commit). Run at every build by the trapdem_build_info target;
# configure_file leaves OUTPUT untouched when nothing changed, so nothing recompiles then.
#   cmake -DSOURCE_DIR=<checkout> -DOUTPUT=<file.cpp> -P write_build_info.cmake
set(commit "")
set(modified "false")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse HEAD
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rev_result ERROR_QUIET)
  if(NOT rev_result EQUAL 0)
    set(commit "")
  else()
    # Tracked files only: a run's output folders and build trees are untracked and change nothing.
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" status --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changes RESULT_VARIABLE status_result ERROR_QUIET)
    if(NOT status_result EQUAL 0 OR NOT changes STREQUAL "")
      set(modified "true")
    endif()
  endif()
endif()
# A source tree without git (an unpacked archive) builds too, its commit unknown (empty).
set(TRAPDEM_BUILD_COMMIT "${commit}")
set(TRAPDEM_BUILD_MODIFIED "${modified}")
configure_file("${CMAKE_CURRENT_LIST_DIR}/build_info.cpp.in" "${OUTPUT}" @ONLY)
