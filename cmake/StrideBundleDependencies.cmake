# cmake -DLIBRARY=<fmu .so> -P StrideBundleDependencies.cmake
# Copies every shared library LIBRARY needs, except the C runtime every Linux machine has, next
# to it, so that with RPATH=$ORIGIN the FMU loads on a machine without our packages.
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES "${LIBRARY}"
  RESOLVED_DEPENDENCIES_VAR resolved
  UNRESOLVED_DEPENDENCIES_VAR unresolved
  PRE_EXCLUDE_REGEXES "^ld-linux" "^linux-vdso" "^libc\\.so" "^libm\\.so" "^libpthread\\.so"
                      "^libdl\\.so" "^librt\\.so")
if(unresolved)
  message(FATAL_ERROR "${LIBRARY}: unresolved shared libraries: ${unresolved}")
endif()
get_filename_component(target_dir "${LIBRARY}" DIRECTORY)
foreach(dependency ${resolved})
  get_filename_component(real "${dependency}" REALPATH)
  get_filename_component(soname "${dependency}" NAME)
  file(COPY_FILE "${real}" "${target_dir}/${soname}" ONLY_IF_DIFFERENT)
endforeach()
