# stride_add_fmu(NAME [IDENTIFIER id] SOURCES src... [LIBS lib...] [RESOURCES file...]
#                [OUTPUT_DIR dir] [BUNDLE_DEPENDENCIES] [INSTALL])
#
# Packages a component as an FMI 2.0 Co-Simulation FMU `<dir>/<NAME>.fmu`, where dir is
# OUTPUT_DIR, else STRIDE_FMU_OUTPUT_DIR, else `${CMAKE_BINARY_DIR}/fmus`:
#  - the component sources (with STRIDE_FMU(model) in one of them) are compiled once, with hidden
#    visibility, and linked both into the FMU's shared library and into a generator executable
#    that writes modelDescription.xml at build time from the component's variable table (given
#    the staged resources/ folder, for a component that reads its interface from there);
#  - the shared library `binaries/linux64/<id>.so` exports only the fmi2* symbols (version
#    script), carries libstdc++/libgcc statically and has RPATH=$ORIGIN;
#  - with BUNDLE_DEPENDENCIES, every shared library it needs beyond the C runtime (libstdc++
#    included, which then is not linked statically) is copied next to it with RPATH=$ORIGIN, so
#    the FMU runs on a machine without our Debian packages (needs patchelf);
#  - RESOURCES land in `resources/`;
#  - with INSTALL, `cmake --install` puts the archive into `share/stride/fmus`, where an installed
#    `stride` finds it by name.
# The same file serves the source tree and an installed Stride (find_package(Stride)): it needs
# only the targets Stride::sdk, Stride::sdk_glue and Stride::sdk_generator.
# Targets: <NAME>_fmu (the .so), <NAME>_fmu_model (objects), <NAME>_model_description
# (generator), <NAME>_fmu_package (the archive). NAME is appended to the global property
# STRIDE_FMU_NAMES, which the FMU conformance tests iterate.
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
  set(archive "${output_dir}/${name}.fmu")

  add_library(${name}_fmu_model OBJECT ${arg_SOURCES})
  target_link_libraries(${name}_fmu_model PUBLIC Stride::sdk ${arg_LIBS})
  set_target_properties(${name}_fmu_model PROPERTIES CXX_VISIBILITY_PRESET hidden
                                                     VISIBILITY_INLINES_HIDDEN ON
                                                     POSITION_INDEPENDENT_CODE ON)
  if(COMMAND stride_set_warnings)
    stride_set_warnings(${name}_fmu_model)
  endif()

  add_library(${name}_fmu SHARED $<TARGET_OBJECTS:Stride::sdk_glue>)
  target_link_libraries(${name}_fmu PRIVATE ${name}_fmu_model)
  set_target_properties(${name}_fmu PROPERTIES
    OUTPUT_NAME ${arg_IDENTIFIER}
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY "${staging}/binaries/linux64"
    BUILD_RPATH "$ORIGIN"
    LINK_DEPENDS "${STRIDE_CMAKE_DIR}/fmu_exports.map")
  # the C++ runtime goes in statically, unless shared libraries are bundled anyway: then the
  # bundled libstdc++ serves all of them, so memory never crosses two runtimes
  if(NOT arg_BUNDLE_DEPENDENCIES)
    target_link_options(${name}_fmu PRIVATE -static-libstdc++ -static-libgcc)
  endif()
  target_link_options(${name}_fmu PRIVATE
    -Wl,--exclude-libs,ALL
    -Wl,--version-script=${STRIDE_CMAKE_DIR}/fmu_exports.map
    -Wl,--disable-new-dtags)  # DT_RPATH, so bundled libraries find each other too
  # every symbol resolved inside the FMU, except in sanitizer builds, where the sanitizer
  # runtime lives in the importing executable
  if(NOT STRIDE_SANITIZE)
    target_link_options(${name}_fmu PRIVATE -Wl,--no-undefined)
  endif()

  add_executable(${name}_model_description $<TARGET_OBJECTS:Stride::sdk_generator>)
  target_link_libraries(${name}_model_description PRIVATE ${name}_fmu_model)

  set(copy_resources "")
  foreach(resource ${arg_RESOURCES})
    get_filename_component(resource "${resource}" ABSOLUTE)
    list(APPEND copy_resources COMMAND ${CMAKE_COMMAND} -E copy "${resource}" "${staging}/resources/")
  endforeach()
  set(bundle "")
  if(arg_BUNDLE_DEPENDENCIES)
    set(bundle COMMAND ${CMAKE_COMMAND} -DLIBRARY=$<TARGET_FILE:${name}_fmu>
                       -P "${STRIDE_CMAKE_DIR}/StrideBundleDependencies.cmake")
  endif()

  add_custom_command(
    OUTPUT "${archive}"
    COMMAND ${CMAKE_COMMAND} -E rm -rf "${staging}/resources"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${staging}/resources" "${output_dir}"
    ${copy_resources}
    COMMAND $<TARGET_FILE:${name}_model_description> "${staging}/modelDescription.xml"
            "${staging}/resources"
    ${bundle}
    COMMAND ${CMAKE_COMMAND} -E rm -f "${archive}"
    COMMAND ${CMAKE_COMMAND} -E chdir "${staging}"
            ${CMAKE_COMMAND} -E tar cf "${archive}" --format=zip
            modelDescription.xml binaries resources
    DEPENDS ${name}_fmu ${name}_model_description ${arg_RESOURCES}
    COMMENT "Packaging ${name}.fmu"
    VERBATIM)
  add_custom_target(${name}_fmu_package ALL DEPENDS "${archive}")
  if(arg_INSTALL)
    install(FILES "${archive}" DESTINATION "${CMAKE_INSTALL_DATADIR}/stride/fmus")
  endif()
  set_property(GLOBAL APPEND PROPERTY STRIDE_FMU_NAMES ${name})
endfunction()
