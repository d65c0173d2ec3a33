# The FMI 3 abuse program (tests/c/fmi3_abuse.c), per model, linked with that model's FMI 3 FMU
# sources; instrumented when AK_SANITIZE is set. build*/fmi3_abuse_<Model>.
foreach(_model IN LISTS AK_FMI3_MODELS)
  add_library(ak_fmu3_for_tests_${_model} STATIC ${AK_MODEL_COMMON_SOURCES} ${AK_MODEL_SOURCES_${_model}}
                                               ${AK_FMI3_ARRAYS_${_model}} ${AK_FMI3_SOURCES}
                                               ${AK_CORE_SOURCES_${_model}})
  target_include_directories(ak_fmu3_for_tests_${_model} PUBLIC ${AK_FMI3_INCLUDE_DIRS}
                             fmu_src/models/${_model} "${FMI2_HEADERS_DIR}")
  target_compile_options(ak_fmu3_for_tests_${_model} PRIVATE ${AK_WARNINGS})
  target_link_libraries(ak_fmu3_for_tests_${_model} PUBLIC m)
  if(NOT AK_FUZZ)
    add_executable(fmi3_abuse_${_model} tests/c/fmi3_abuse.c)
    target_compile_options(fmi3_abuse_${_model} PRIVATE ${AK_WARNINGS})
    target_link_libraries(fmi3_abuse_${_model} PRIVATE ak_fmu3_for_tests_${_model} Threads::Threads)
    add_test(NAME fmi3_calls_${_model} COMMAND fmi3_abuse_${_model} calls)
    add_test(NAME fmi3_instances_${_model} COMMAND fmi3_abuse_${_model} instances 200 4 30)
    add_test(NAME fmi3_parallel_${_model} COMMAND fmi3_abuse_${_model} parallel 20000)
    add_test(NAME fmi3_soak_short_${_model} COMMAND fmi3_abuse_${_model} soak 100000)
  else()
    add_executable(fuzz_fmi3_${_model} tests/c/fuzz_fmi3.c)
    target_compile_options(fuzz_fmi3_${_model} PRIVATE ${AK_WARNINGS})
    target_link_libraries(fuzz_fmi3_${_model} PRIVATE ak_fmu3_for_tests_${_model})
    target_link_options(fuzz_fmi3_${_model} PRIVATE -fsanitize=fuzzer)
  endif()
endforeach()
