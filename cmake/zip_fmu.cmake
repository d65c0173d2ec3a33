# Packs a staged FMU folder into a zip archive that depends on the files' contents alone: the
# entries in sorted order, each with the same fixed date, so that two builds of the same sources
# give byte-identical .fmu files (scripts/release.sh checks it).
#   cmake -DPACKAGE=<staged folder> -DARCHIVE=<file.fmu> -P cmake/zip_fmu.cmake
file(GLOB_RECURSE _files RELATIVE "${PACKAGE}" LIST_DIRECTORIES false "${PACKAGE}/*")
list(SORT _files)
file(REMOVE "${ARCHIVE}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E tar cf "${ARCHIVE}" --format=zip "--mtime=1980-01-02 00:00:00 UTC"
          -- ${_files}
  WORKING_DIRECTORY "${PACKAGE}"
  RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "packing ${ARCHIVE} failed")
endif()
