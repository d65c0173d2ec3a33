# The abuse tests (docs/abuse_testing.md): C programs that link an FMU's own sources and play the
# master, one set per model. Built in every Linux build folder; instrumented when AK_SANITIZE is
# set (cmake/sanitizers.cmake). The AngularKinematics programs keep the plain names
# (build/test_fmi2_calls ...), the others end in _<Model> (build/test_fmi2_calls_EulerRates).
find_package(Threads REQUIRED)

# ak_add_abuse_tests(<model> <rows file> [NO_INSTANCES_OR_SOAK]): the call driver
# test_fmi2_calls (its bad-input table) and, in a fuzz build, the fuzzer fuzz_fmi2, for every
# model; the many-instance and soak programs unless NO_INSTANCES_OR_SOAK.
function(ak_add_abuse_tests model rows_source)
  cmake_parse_arguments(_ARG "NO_INSTANCES_OR_SOAK" "" "" ${ARGN})
  if(model STREQUAL "AngularKinematics")
    set(_suffix "")
  else()
    set(_suffix "_${model}")
  endif()
  # The FMU's sources, compiled once more as a static library the test programs link.
  add_library(ak_fmu_for_tests_${model} STATIC ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${model}}
                                              ${AK_FMI2_SOURCES})
  target_include_directories(ak_fmu_for_tests_${model} PUBLIC ${AK_INCLUDE_DIRS}
                             fmu_src/models/${model} "${FMI2_HEADERS_DIR}")
  target_compile_options(ak_fmu_for_tests_${model} PRIVATE ${AK_WARNINGS})
  target_link_libraries(ak_fmu_for_tests_${model} PUBLIC kinematics_core)

  # The master's side shared by the programs: callbacks, the op table, state helpers, the
  # bad-input table (rows common to both models and the model's own rows).
  add_library(ak_test_master_${model} STATIC
    tests/c/fmi2_test_callbacks.c
    tests/c/fmi2_test_ops.c
    tests/c/fmi2_test_instance.c
    tests/c/fmi2_bad_input_table.c
    tests/c/${rows_source})
  target_compile_options(ak_test_master_${model} PRIVATE ${AK_WARNINGS})
  # The rows of the bad-input tables list the fields every row has, in order, and leave the
  # optional ones (fmi2_bad_input_table.h: setup call, second message, ...) zero.
  set_source_files_properties(tests/c/fmi2_bad_input_table.c tests/c/${rows_source}
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
  if(NOT _ARG_NO_INSTANCES_OR_SOAK)
    add_executable(test_fmi2_instances${_suffix} tests/c/test_fmi2_instances.c)
    target_compile_options(test_fmi2_instances${_suffix} PRIVATE ${AK_WARNINGS})
    target_link_libraries(test_fmi2_instances${_suffix} PRIVATE ak_test_master_${model}
                                                                Threads::Threads)
    add_test(NAME fmi2_instances_${model} COMMAND test_fmi2_instances${_suffix} 1000 4 20)

    add_executable(soak_fmi2${_suffix} tests/c/soak_fmi2.c)
    target_compile_options(soak_fmi2${_suffix} PRIVATE ${AK_WARNINGS})
    target_link_libraries(soak_fmi2${_suffix} PRIVATE ak_test_master_${model})
    add_test(NAME fmi2_soak_short_${model} COMMAND soak_fmi2${_suffix} 100000)
  endif()
endfunction()

ak_add_abuse_tests(AngularKinematics fmi2_bad_input_angular_kinematics.c)
ak_add_abuse_tests(EulerRates fmi2_bad_input_euler_rates.c)

# AttitudePropagator (the first model with continuous states, 6 inputs): the call driver, its
# bad-input table and the fuzzer like the others; for many instances in threads and random calls
# with bad arguments in both interfaces, its own abuse program (tests/c/abuse_attitude.c) until
# the many-instance and soak programs above cover it.
ak_add_abuse_tests(AttitudePropagator fmi2_bad_input_attitude_propagator.c NO_INSTANCES_OR_SOAK)
if(NOT AK_FUZZ)
  add_executable(abuse_attitude tests/c/abuse_attitude.c)
  target_compile_options(abuse_attitude PRIVATE ${AK_WARNINGS})
  target_link_libraries(abuse_attitude PRIVATE ak_fmu_for_tests_AttitudePropagator Threads::Threads)
  add_test(NAME abuse_AttitudePropagator COMMAND abuse_attitude 4 50 200 200000)
endif()
