# The reference result an FMU carries (FMI-LS-REF, scripts/make_ls_ref.py), made while packaging
# from the binary just built: the package is zipped once without it, fmpy runs the experiment on
# that FMU, and the files land in the package before the final zip. So a clean tree (a new model
# too) packages its FMUs with results that are what they compute.
set(AK_LS_REF_WRITERS
    "${CMAKE_SOURCE_DIR}/scripts/make_ls_ref.py" "${CMAKE_SOURCE_DIR}/scripts/make_cross_check.py"
    "${CMAKE_SOURCE_DIR}/examples/cross_check.py" "${CMAKE_SOURCE_DIR}/examples/cross_check3.py"
    "${CMAKE_SOURCE_DIR}/examples/ls_ref.py")

# Sets AK_LS_REF_COMMANDS in the caller: the COMMAND lines that write the files into package.
# None in a sanitizer build: its binaries load only under the sanitizer's runtime, and its FMUs
# serve the abuse tests (scripts/check_sanitizers.sh), which do not read the reference.
function(ak_ls_ref_commands package unreferenced)
  if(AK_SANITIZE)
    set(AK_LS_REF_COMMANDS "" PARENT_SCOPE)
    return()
  endif()
  set(AK_LS_REF_COMMANDS
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/tools/zip_fmu.py" "${package}" "${unreferenced}"
      # as a module from the checkout: the demo's .venv has no editable install of the project
      COMMAND ${CMAKE_COMMAND} -E chdir "${CMAKE_SOURCE_DIR}" "${Python3_EXECUTABLE}" -m scripts.make_ls_ref
              "${unreferenced}" "${package}/extra/org.fmi-standard.fmi-ls-ref"
      PARENT_SCOPE)
endfunction()
