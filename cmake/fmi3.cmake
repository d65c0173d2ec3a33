# The FMI 3.0 FMUs: per model a shared library <Model>_fmi3 (output name <Model>) from
# the same kinematics core and model folder as the FMI 2 one, with the FMI 3 layer fmu_src/fmi3/
# instead of fmu_src/fmi2/; staged in build*/fmu3/binaries/<FMI 3 platform>/ and packaged, by the
# build that packages (preset release), as dist/fmi3/<Model>.fmu with the binaries of the other
# builds (AK_EXTRA_FMI3_BINARIES: windows, aarch64, riscv64 and darwin presets).
set(AK_EXTRA_FMI3_BINARIES "" CACHE STRING
    "FMI 3 binaries of other builds to add to dist/fmi3/*.fmu, each as .../<platform>/<Model>.<ext>")

# FMI 3.0 platform tuple (section 2.5.1.1): <arch>-<sys>.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(_arch x86_64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64|ARM64)$")
  set(_arch aarch64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^riscv64$")
  set(_arch riscv64)
else()
  set(_arch ${CMAKE_SYSTEM_PROCESSOR})
endif()
string(TOLOWER "${CMAKE_SYSTEM_NAME}" _system)
if(_system STREQUAL "darwin")
  set(_system darwin)
endif()
set(FMI3_PLATFORM "${_arch}-${_system}")
message(STATUS "FMI 3 platform: ${FMI3_PLATFORM}")
if(NOT EXISTS "${FMI2_HEADERS_DIR}/fmi3Functions.h")
  message(FATAL_ERROR "No fmi3Functions.h beside fmi2Functions.h in ${FMI2_HEADERS_DIR} (fmpy >= 0.3)")
endif()

set(FMU3_STAGING_DIR "${CMAKE_BINARY_DIR}/fmu3")
set(AK_FMI3_INCLUDE_DIRS fmu_src/core fmu_src/elementary fmu_src/models fmu_src/runtime fmu_src/fmi3 fmu_src/common)

function(ak_add_fmu3 model)
  set(_target ${model}_fmi3)
  set(_sources ${AK_CORE_SOURCES_${model}} ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${model}}
               ${AK_FMI3_ARRAYS_${model}} ${AK_FMI3_SOURCES})
  set(_headers ${AK_CORE_HEADERS_${model}} ${AK_FMI3_HEADERS} ${AK_MODEL_HEADERS_${model}})
  add_library(${_target} SHARED ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${model}}
                                ${AK_FMI3_ARRAYS_${model}} ${AK_FMI3_SOURCES}
                                ${AK_CORE_SOURCES_${model}})  # the model's core sources, as the FMI 2 binary
  target_include_directories(${_target} PRIVATE ${AK_FMI3_INCLUDE_DIRS} fmu_src/models/${model}
                                                "${FMI2_HEADERS_DIR}")
  target_compile_options(${_target} PRIVATE ${AK_WARNINGS})
  if(NOT WIN32)
    target_link_libraries(${_target} PRIVATE m)
  endif()
  set_target_properties(${_target} PROPERTIES
    OUTPUT_NAME ${model}
    PREFIX ""
    C_VISIBILITY_PRESET hidden
    LIBRARY_OUTPUT_DIRECTORY "${FMU3_STAGING_DIR}/binaries/${FMI3_PLATFORM}"
    RUNTIME_OUTPUT_DIRECTORY "${FMU3_STAGING_DIR}/binaries/${FMI3_PLATFORM}")
  if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
    target_link_options(${_target} PRIVATE -Wl,--no-undefined)
  endif()
  if(MINGW)
    target_link_options(${_target} PRIVATE ${AK_MINGW_FMU_LINK_OPTIONS})  # as the FMI 2 DLL's
  endif()

  if(NOT AK_PACKAGE_FMU)
    return()
  endif()
  set(_packaged "")
  foreach(_file IN LISTS _sources _headers)
    list(APPEND _packaged "${CMAKE_SOURCE_DIR}/${_file}")
  endforeach()
  set(_folder "${CMAKE_SOURCE_DIR}/fmu_src/models/${model}/fmi3")
  set(_package "${CMAKE_BINARY_DIR}/fmu3_package_${model}")
  set(_copy_extra "")
  set(_extra "")
  foreach(_binary IN LISTS AK_EXTRA_FMI3_BINARIES)
    get_filename_component(_stem "${_binary}" NAME_WE)
    if(NOT _stem STREQUAL model)
      continue()
    endif()
    get_filename_component(_platform_dir "${_binary}" DIRECTORY)
    get_filename_component(_platform "${_platform_dir}" NAME)
    list(APPEND _extra "${_binary}")
    list(APPEND _copy_extra
         COMMAND ${CMAKE_COMMAND} -E make_directory "${_package}/binaries/${_platform}"
         COMMAND ${CMAKE_COMMAND} -E copy "${_binary}" "${_package}/binaries/${_platform}/")
  endforeach()
  list(TRANSFORM AK_DOCUMENTATION_FIGURES_${model} PREPEND "${CMAKE_SOURCE_DIR}/"
       OUTPUT_VARIABLE _figures)
  set(_fmu "${AK_DIST_DIR}/fmi3/${model}.fmu")
  ak_ls_ref_commands("${_package}" "${CMAKE_BINARY_DIR}/fmu3_unreferenced_${model}.fmu")
  add_custom_command(
    OUTPUT "${_fmu}"
    COMMAND ${CMAKE_COMMAND} -E rm -rf "${_package}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${_package}/binaries/${FMI3_PLATFORM}"
            "${_package}/sources" "${_package}/documentation" "${_package}/terminalsAndIcons"
    COMMAND ${CMAKE_COMMAND} -E copy "${_folder}/modelDescription.xml" "${_package}/"
    COMMAND ${CMAKE_COMMAND} -E copy "${_folder}/documentation/index.html" ${_figures}
            "${_package}/documentation/"
    COMMAND ${CMAKE_COMMAND} -E copy "${CMAKE_SOURCE_DIR}/model.png"
            "${_package}/terminalsAndIcons/icon.png"
    COMMAND ${CMAKE_COMMAND} -E copy ${_packaged} "${_package}/sources/"
    COMMAND ${CMAKE_COMMAND} -E copy "${_folder}/buildDescription.xml" "${_package}/sources/"
    COMMAND ${CMAKE_COMMAND} -E copy "$<TARGET_FILE:${_target}>"
            "${_package}/binaries/${FMI3_PLATFORM}/"
    ${_copy_extra}
    ${AK_LS_REF_COMMANDS}
    COMMAND ${CMAKE_COMMAND} -E make_directory "${AK_DIST_DIR}/fmi3"
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/tools/zip_fmu.py" "${_package}" "${_fmu}"
    WORKING_DIRECTORY "${CMAKE_BINARY_DIR}"
    DEPENDS ${_target} "${_folder}/modelDescription.xml" "${_folder}/buildDescription.xml"
            "${_folder}/documentation/index.html" ${_figures} "${CMAKE_SOURCE_DIR}/model.png" ${_packaged}
            ${_extra} ${AK_LS_REF_WRITERS} "${CMAKE_SOURCE_DIR}/tools/zip_fmu.py"
    COMMENT "Packaging ${_fmu}"
    VERBATIM)
  add_custom_target(fmu3_${model} ALL DEPENDS "${_fmu}")
endfunction()

foreach(_model IN LISTS AK_MODELS)
  ak_add_fmu3(${_model})
endforeach()

# Every model's FMI 3 binary, for the builds that only make another platform's (scripts/build.sh).
list(TRANSFORM AK_MODELS APPEND _fmi3 OUTPUT_VARIABLE _fmi3_targets)
add_custom_target(fmi3_binaries DEPENDS ${_fmi3_targets})

# Our FMI 3 master: runs a fixed scenario through one FMI 3 binary and prints every output in
# hex, so that the binaries of x86_64-linux, aarch64-linux and riscv64-linux (under qemu) and
# x86_64-windows (under wine) can be compared bit for bit (tests/python/test_fmi3_platforms.py);
# its cross-check mode computes dist/cross-check/'s results with each platform's binary.
add_executable(fmi3_driver tools/fmi3_driver.c tools/fmi3_driver_cross_check.c tools/driver_rows.c
                           tools/fmi3_driver_models.c) # models: generated
target_include_directories(fmi3_driver PRIVATE "${FMI2_HEADERS_DIR}" ${CMAKE_SOURCE_DIR}/tools)
target_compile_options(fmi3_driver PRIVATE ${AK_WARNINGS})
target_link_libraries(fmi3_driver PRIVATE ${CMAKE_DL_LIBS})
if(MINGW)
  target_link_options(fmi3_driver PRIVATE -static)
endif()
