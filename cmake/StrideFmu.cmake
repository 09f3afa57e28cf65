# stride_add_fmu(NAME [IDENTIFIER id] SOURCES src... [LIBS lib...] [RESOURCES file...]
#                [OUTPUT_DIR dir] [BUNDLE_DEPENDENCIES] [INSTALL])
#
# Packages a component twice from the same sources and variable table: as an FMI 2.0
# Co-Simulation FMU `<dir>/<NAME>.fmu` and as an FMI 3.0 Co-Simulation FMU
# `<dir>/fmi3/<NAME>.fmu`, where dir is OUTPUT_DIR, else STRIDE_FMU_OUTPUT_DIR, else
# `${CMAKE_BINARY_DIR}/fmus`:
#  - the component sources (with STRIDE_FMU(model) in one of them) are compiled once, with hidden
#    visibility, and linked into each FMU's shared library (with the 2.0 or the 3.0 glue) and into
#    a generator executable that writes modelDescription.xml (2.0, or 3.0 with --fmi3) at build
#    time from the component's variable table (given the staged resources/ folder, for a
#    component that reads its interface from there);
#  - the shared library `binaries/linux64/<id>.so` (2.0) or `binaries/x86_64-linux/<id>.so`
#    (3.0) exports only the fmi2* or fmi3* symbols (version script), carries libstdc++/libgcc
#    statically and has RPATH=$ORIGIN;
#  - with BUNDLE_DEPENDENCIES, every shared library it needs beyond the C runtime (libstdc++
#    included, which then is not linked statically) is copied next to it with RPATH=$ORIGIN, so
#    the FMU runs on a machine without our Debian packages (needs patchelf);
#  - RESOURCES land in `resources/`;
#  - with INSTALL, `cmake --install` puts the archives into `share/stride/fmus` (and its `fmi3/`),
#    where an installed `stride` finds them by name.
# The same file serves the source tree and an installed Stride (find_package(Stride)): it needs
# only the targets Stride::sdk, Stride::sdk_glue, Stride::sdk_glue3 and Stride::sdk_generator.
# Targets: <NAME>_fmu and <NAME>_fmu3 (the .so files), <NAME>_fmu_model (objects),
# <NAME>_model_description (generator), <NAME>_fmu_package (both archives). NAME is appended to
# the global property STRIDE_FMU_NAMES, which the FMU conformance tests iterate.
include(GNUInstallDirs)
set_property(GLOBAL PROPERTY STRIDE_FMU_NAMES "")
set(STRIDE_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}" CACHE INTERNAL "")

function(stride_add_fmu name)
  cmake_parse_arguments(arg "BUNDLE_DEPENDENCIES;INSTALL" "IDENTIFIER;OUTPUT_DIR"
                        "SOURCES;LIBS;RESOURCES" ${ARGN})
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "stride_add_fmu(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_SOURCES)
    message(FATAL_ERROR "stride_add_fmu(${name}): SOURCES is required")
  endif()
  if(NOT arg_IDENTIFIER)
    set(arg_IDENTIFIER ${name})
  endif()
  if(NOT arg_IDENTIFIER MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "stride_add_fmu(${name}): the model identifier '${arg_IDENTIFIER}' must be "
                        "a C identifier (it names the binary and prefixes its functions)")
  endif()
  set(output_dir "${arg_OUTPUT_DIR}")
  if(NOT output_dir)
    set(output_dir "${STRIDE_FMU_OUTPUT_DIR}")
  endif()
  if(NOT output_dir)
    set(output_dir "${CMAKE_BINARY_DIR}/fmus")
  endif()
  set(staging "${CMAKE_CURRENT_BINARY_DIR}/${name}.fmu.d")
  set(staging3 "${CMAKE_CURRENT_BINARY_DIR}/${name}.fmu3.d")
  set(archive "${output_dir}/${name}.fmu")
  set(archive3 "${output_dir}/fmi3/${name}.fmu")

  add_library(${name}_fmu_model OBJECT ${arg_SOURCES})
  target_link_libraries(${name}_fmu_model PUBLIC Stride::sdk ${arg_LIBS})
  set_target_properties(${name}_fmu_model PROPERTIES CXX_VISIBILITY_PRESET hidden
                                                     VISIBILITY_INLINES_HIDDEN ON
                                                     POSITION_INDEPENDENT_CODE ON)
  if(COMMAND stride_set_warnings)
    stride_set_warnings(${name}_fmu_model)
  endif()

  _stride_fmu_library(${name}_fmu Stride::sdk_glue ${name}_fmu_model ${arg_IDENTIFIER}
                      "${staging}/binaries/linux64" fmu_exports.map ${arg_BUNDLE_DEPENDENCIES})
  _stride_fmu_library(${name}_fmu3 Stride::sdk_glue3 ${name}_fmu_model ${arg_IDENTIFIER}
                      "${staging3}/binaries/x86_64-linux" fmu3_exports.map
                      ${arg_BUNDLE_DEPENDENCIES})

  add_executable(${name}_model_description $<TARGET_OBJECTS:Stride::sdk_generator>)
  target_link_libraries(${name}_model_description PRIVATE ${name}_fmu_model)

  _stride_fmu_archive(${name} "${archive}" "${staging}" ${name}_fmu "" "${arg_RESOURCES}"
                      ${arg_BUNDLE_DEPENDENCIES})
  _stride_fmu_archive(${name} "${archive3}" "${staging3}" ${name}_fmu3 --fmi3 "${arg_RESOURCES}"
                      ${arg_BUNDLE_DEPENDENCIES})
  add_custom_target(${name}_fmu_package ALL DEPENDS "${archive}" "${archive3}")
  if(arg_INSTALL)
    install(FILES "${archive}" DESTINATION "${CMAKE_INSTALL_DATADIR}/stride/fmus")
    install(FILES "${archive3}" DESTINATION "${CMAKE_INSTALL_DATADIR}/stride/fmus/fmi3")
  endif()
  set_property(GLOBAL APPEND PROPERTY STRIDE_FMU_NAMES ${name})
endfunction()

# The shared library of one FMU for one standard: the component's objects plus that standard's
# glue, exporting only its functions.
function(_stride_fmu_library target glue model identifier dir exports_map bundle)
  add_library(${target} SHARED $<TARGET_OBJECTS:${glue}>)
  target_link_libraries(${target} PRIVATE ${model})
  set_target_properties(${target} PROPERTIES
    OUTPUT_NAME ${identifier}
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY "${dir}"
    BUILD_RPATH "$ORIGIN"
    LINK_DEPENDS "${STRIDE_CMAKE_DIR}/${exports_map}")
  # the C++ runtime goes in statically, unless shared libraries are bundled anyway: then the
  # bundled libstdc++ serves all of them, so memory never crosses two runtimes
  if(NOT bundle)
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
  endif()
  target_link_options(${target} PRIVATE
    -Wl,--exclude-libs,ALL
    -Wl,--version-script=${STRIDE_CMAKE_DIR}/${exports_map}
    -Wl,--disable-new-dtags)  # DT_RPATH, so bundled libraries find each other too
  # every symbol resolved inside the FMU, except in sanitizer builds, where the sanitizer
  # runtime lives in the importing executable
  if(NOT STRIDE_SANITIZE)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
endfunction()

# The archive of one FMU for one standard; `version_flag` is passed to the generator ("" or
# --fmi3).
function(_stride_fmu_archive name archive staging library version_flag resources bundle)
  get_filename_component(output_dir "${archive}" DIRECTORY)
  set(copy_resources "")
  foreach(resource ${resources})
    get_filename_component(resource "${resource}" ABSOLUTE)
    list(APPEND copy_resources COMMAND ${CMAKE_COMMAND} -E copy "${resource}" "${staging}/resources/")
  endforeach()
  set(bundle_command "")
  if(bundle)
    set(bundle_command COMMAND ${CMAKE_COMMAND} -DLIBRARY=$<TARGET_FILE:${library}>
                               -P "${STRIDE_CMAKE_DIR}/StrideBundleDependencies.cmake")
  endif()
  add_custom_command(
    OUTPUT "${archive}"
    COMMAND ${CMAKE_COMMAND} -E rm -rf "${staging}/resources"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${staging}/resources" "${output_dir}"
    ${copy_resources}
    COMMAND $<TARGET_FILE:${name}_model_description> ${version_flag}
            "${staging}/modelDescription.xml" "${staging}/resources"
    ${bundle_command}
    COMMAND ${CMAKE_COMMAND} -E rm -f "${archive}"
    COMMAND ${CMAKE_COMMAND} -E chdir "${staging}"
            ${CMAKE_COMMAND} -E tar cf "${archive}" --format=zip
            modelDescription.xml binaries resources
    DEPENDS ${library} ${name}_model_description ${resources}
    COMMENT "Packaging ${archive}"
    VERBATIM)
endfunction()
