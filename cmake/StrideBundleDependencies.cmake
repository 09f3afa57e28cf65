# cmake -DLIBRARY=<fmu .so> -P StrideBundleDependencies.cmake
# Copies every shared library LIBRARY needs, except the C runtime every Linux machine has, next
# to it, so that with RPATH=$ORIGIN the FMU loads on a machine without our packages.
find_program(PATCHELF patchelf REQUIRED)

# start from the library alone, so copies from an earlier run are not found through $ORIGIN
get_filename_component(target_dir "${LIBRARY}" DIRECTORY)
file(GLOB previous "${target_dir}/*.so*")
list(REMOVE_ITEM previous "${LIBRARY}")
if(previous)
  file(REMOVE ${previous})
endif()

file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES "${LIBRARY}"
  RESOLVED_DEPENDENCIES_VAR resolved
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  PRE_EXCLUDE_REGEXES "^ld-linux" "^linux-vdso" "^libc\\.so" "^libm\\.so" "^libpthread\\.so"
                      "^libdl\\.so" "^librt\\.so")
if(unresolved)
  message(FATAL_ERROR "${LIBRARY}: unresolved shared libraries: ${unresolved}")
endif()
foreach(dependency ${resolved})
  get_filename_component(real "${dependency}" REALPATH)
  get_filename_component(soname "${dependency}" NAME)
  file(COPY_FILE "${real}" "${target_dir}/${soname}")
  # each bundled library finds its bundled neighbours by itself
  execute_process(COMMAND "${PATCHELF}" --set-rpath "$ORIGIN" "${target_dir}/${soname}"
                  RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "patchelf failed on ${target_dir}/${soname}")
  endif()
endforeach()
