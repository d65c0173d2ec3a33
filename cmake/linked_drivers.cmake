# Static drivers with one model's FMI functions linked in (AK_LINKED_DRIVERS, preset x86-musl):
# fmu_driver_<Model> (FMI 2) and fmi3_driver_<Model> (FMI 3), built from exactly the sources of
# the model's FMU binary (its core sources among them), for a platform whose shared libraries cannot be
# loaded here (the 32-bit x86 proof build, docs/platforms.md; tests/python/test_platforms.py runs
# them).
set(_linked_drivers "")
foreach(_model IN LISTS AK_MODELS)
  # The driver's table of the other models' variables; this model's comes with its sources.
  set(_tables "")
  foreach(_other IN LISTS AK_MODELS)
    if(NOT _other STREQUAL _model)
      list(APPEND _tables fmu_src/models/${_other}/${_other}_variables.c)
    endif()
  endforeach()
  add_executable(fmu_driver_${_model} tools/fmu_driver.c tools/fmu_driver_cross_check.c
                 tools/driver_rows.c tools/fmu_driver_models.c ${_tables}
                 ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${_model}} ${AK_FMI2_SOURCES}
                 ${AK_CORE_SOURCES_${_model}})
  target_include_directories(fmu_driver_${_model} PRIVATE ${AK_INCLUDE_DIRS} ${AK_MODEL_FOLDERS}
                             tools "${FMI2_HEADERS_DIR}")
  add_executable(fmi3_driver_${_model} tools/fmi3_driver.c tools/fmi3_driver_cross_check.c
                 tools/driver_rows.c tools/fmi3_driver_models.c
                 ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${_model}}
                 ${AK_FMI3_ARRAYS_${_model}} ${AK_FMI3_SOURCES} ${AK_CORE_SOURCES_${_model}})
  target_include_directories(fmi3_driver_${_model} PRIVATE ${AK_FMI3_INCLUDE_DIRS}
                             fmu_src/models/${_model} "${FMI2_HEADERS_DIR}" tools)
  foreach(_driver fmu_driver_${_model} fmi3_driver_${_model})
    target_compile_definitions(${_driver} PRIVATE AK_DRIVER_LINKED)
    target_compile_options(${_driver} PRIVATE ${AK_WARNINGS})
    target_link_libraries(${_driver} PRIVATE m)
    target_link_options(${_driver} PRIVATE -static)
    list(APPEND _linked_drivers ${_driver})
  endforeach()
endforeach()
add_custom_target(linked_drivers DEPENDS ${_linked_drivers})
