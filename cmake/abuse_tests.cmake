# The abuse tests (docs/abuse_testing.md): C programs that link an FMU's own sources and play the
# master, one set per model, each program named for its model (build/test_fmi2_calls_<Model>).
# Built in every Linux build folder; instrumented when AK_SANITIZE is set
# (cmake/sanitizers.cmake).
find_package(Threads REQUIRED)

# ak_add_abuse_tests(<model>): the call driver test_fmi2_calls_<Model> (its bad-input table: the
# rows every model has, tests/c/fmi2_bad_input_table.c, and the model's own,
# fmu_src/models/<Model>/tests/bad_input_rows.c), the many-instance and soak programs and, in a
# fuzz build, the fuzzer fuzz_fmi2_<Model>.
function(ak_add_abuse_tests model)
  set(_rows fmu_src/models/${model}/tests/bad_input_rows.c)
  set(_suffix "_${model}")
  # The FMU's sources (its core sources among them), compiled once more as a static library the
  # test programs link.
  add_library(ak_fmu_for_tests_${model} STATIC ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${model}}
                                              ${AK_FMI2_SOURCES} ${AK_CORE_SOURCES_${model}})
  target_include_directories(ak_fmu_for_tests_${model} PUBLIC ${AK_INCLUDE_DIRS}
                             fmu_src/models/${model} "${FMI2_HEADERS_DIR}")
  target_compile_options(ak_fmu_for_tests_${model} PRIVATE ${AK_WARNINGS})
  target_link_libraries(ak_fmu_for_tests_${model} PUBLIC m)

  # The master's side shared by the programs: callbacks, the op table, state helpers, the
  # bad-input table (rows common to both models and the model's own rows).
  add_library(ak_test_master_${model} STATIC
    tests/c/fmi2_test_callbacks.c
    tests/c/fmi2_test_ops.c
    tests/c/fmi2_test_instance.c
    tests/c/fmi2_bad_input_table.c
    ${_rows})
  target_include_directories(ak_test_master_${model} PUBLIC tests/c)
  target_compile_options(ak_test_master_${model} PRIVATE ${AK_WARNINGS})
  # The rows of the bad-input tables list the fields every row has, in order, and leave the
  # optional ones (fmi2_bad_input_table.h: setup call, second message, ...) zero.
  set_source_files_properties(tests/c/fmi2_bad_input_table.c ${_rows}
                              PROPERTIES COMPILE_OPTIONS -Wno-missing-field-initializers)
  target_link_libraries(ak_test_master_${model} PUBLIC ak_fmu_for_tests_${model}
                                                      kinematics_123_reference)

  if(AK_FUZZ)
    add_executable(fuzz_fmi2${_suffix} tests/c/fuzz_fmi2.c)
    target_compile_options(fuzz_fmi2${_suffix} PRIVATE ${AK_WARNINGS})
    target_link_libraries(fuzz_fmi2${_suffix} PRIVATE ak_test_master_${model})
    target_link_options(fuzz_fmi2${_suffix} PRIVATE -fsanitize=fuzzer)
    return()
  endif()
  add_executable(test_fmi2_calls${_suffix} tests/c/test_fmi2_calls.c)
  target_compile_options(test_fmi2_calls${_suffix} PRIVATE ${AK_WARNINGS})
  target_link_libraries(test_fmi2_calls${_suffix} PRIVATE ak_test_master_${model})
  add_test(NAME fmi2_calls_${model} COMMAND test_fmi2_calls${_suffix})

  add_executable(test_fmi2_instances${_suffix} tests/c/test_fmi2_instances.c)
  target_compile_options(test_fmi2_instances${_suffix} PRIVATE ${AK_WARNINGS})
  target_link_libraries(test_fmi2_instances${_suffix} PRIVATE ak_test_master_${model}
                                                              Threads::Threads)
  add_test(NAME fmi2_instances_${model} COMMAND test_fmi2_instances${_suffix} 1000 4 20)

  add_executable(soak_fmi2${_suffix} tests/c/soak_fmi2.c)
  target_compile_options(soak_fmi2${_suffix} PRIVATE ${AK_WARNINGS})
  target_link_libraries(soak_fmi2${_suffix} PRIVATE ak_test_master_${model})
  add_test(NAME fmi2_soak_short_${model} COMMAND soak_fmi2${_suffix} 100000)
endfunction()

foreach(_model IN LISTS AK_MODELS)
  ak_add_abuse_tests(${_model})
endforeach()
# Random calls with bad arguments in both interfaces on many threads, for the model with
# continuous states (tests/c/abuse_attitude.c).
if(NOT AK_FUZZ)
  add_executable(abuse_attitude tests/c/abuse_attitude.c)
  target_compile_options(abuse_attitude PRIVATE ${AK_WARNINGS})
  target_link_libraries(abuse_attitude PRIVATE ak_fmu_for_tests_AttitudePropagator Threads::Threads)
  add_test(NAME abuse_AttitudePropagator COMMAND abuse_attitude 4 50 200 200000)
endif()
