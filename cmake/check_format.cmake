# cmake -DSOURCE_DIR=<repo> -DCLANG_FORMAT=<exe> -P check_format.cmake
# Fails when any C/C++ source of the project differs from what .clang-format prescribes.
set(files "")
foreach(dir common fmi components orchestrator suite remote study viewer cli tests bench calibration examples fuzz)
  file(GLOB_RECURSE found "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.hpp"
                          "${SOURCE_DIR}/${dir}/*.c" "${SOURCE_DIR}/${dir}/*.h")
  list(APPEND files ${found})
endforeach()
execute_process(COMMAND "${CLANG_FORMAT}" --dry-run --Werror ${files}
                RESULT_VARIABLE failed ERROR_VARIABLE report)
if(failed)
  message(FATAL_ERROR "files not formatted (run clang-format -i on them):\n${report}")
endif()
list(LENGTH files count)
message(STATUS "${count} files formatted as .clang-format prescribes")
