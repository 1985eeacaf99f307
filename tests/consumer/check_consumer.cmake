# Installs brdftab into a scratch prefix, builds tests/consumer against it with
# find_package(brdftab), and runs it on the committed demo table.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
    -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer ${SOURCE_DIR}/tables)
# The installed default tables, found through the library's default search (BRDFTAB_TABLES).
run(${CMAKE_COMMAND} -E env BRDFTAB_TABLES=${WORK_DIR}/prefix/share/brdftab/tables ${WORK_DIR}/build/consumer)
# pkg-config file and licence installed.
foreach(f lib/pkgconfig/brdftab.pc share/doc/brdftab/LICENSE include/brdftab/lookup/version.hpp)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
