# Installs brdftab into a scratch prefix, builds tests/consumer against it with
# find_package(brdftab) (a CXX-only project) and with pkg-config's flags alone, and runs
# both on the committed demo table. Every include is <brdftab/...>.
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
# Without BRDFTAB_TABLES: the installed tables, found relative to the installed library
# (the scratch prefix is not the configured CMAKE_INSTALL_PREFIX).
run(${CMAKE_COMMAND} -E env --unset=BRDFTAB_TABLES ${WORK_DIR}/build/consumer)
# pkg-config file, licence, version header and headers installed under include/brdftab/.
foreach(f lib/pkgconfig/brdftab.pc share/doc/brdftab/LICENSE include/brdftab/lookup/version.hpp
          include/brdftab/lookup/table_set.hpp)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
# The installed CLI runs (it finds the installed shared library through its rpath) and
# reads the installed tables by default from a folder without tables/.
execute_process(COMMAND ${WORK_DIR}/prefix/bin/brdftab info demo.h5 WORKING_DIRECTORY ${WORK_DIR}/prefix/share/brdftab/tables
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "demo_exp_cos")
  message(FATAL_ERROR "installed brdftab info failed (${rc}):\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=BRDFTAB_TABLES ${WORK_DIR}/prefix/bin/brdftab eval demo_exp_cos --method table
                INPUT_FILE ${SOURCE_DIR}/tests/consumer/demo_input.csv WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "0.8,0.6,0.3708468")
  message(FATAL_ERROR "installed brdftab eval --method table (installed tables) failed (${rc}):\n${out}${err}")
endif()
# pkg-config (relocatable .pc: the scratch prefix, not the configured one): compile and run
# the same program with its flags alone.
find_program(PKG_CONFIG pkg-config)
if(NOT PKG_CONFIG)
  message(FATAL_ERROR "pkg-config not found (Debian pkg-config; scripts/install-deps.sh)")
endif()
set(ENV{PKG_CONFIG_PATH} ${WORK_DIR}/prefix/lib/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG} --cflags --libs brdftab RESULT_VARIABLE rc OUTPUT_VARIABLE flags
                ERROR_VARIABLE perr OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs brdftab failed: ${perr}")
endif()
execute_process(COMMAND ${PKG_CONFIG} --variable=tablesdir brdftab OUTPUT_VARIABLE tablesdir
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT EXISTS ${tablesdir}/demo.h5)
  message(FATAL_ERROR "pkg-config tablesdir '${tablesdir}' has no demo.h5")
endif()
message(STATUS "pkg-config: ${flags}; tablesdir ${tablesdir}")
separate_arguments(flag_list UNIX_COMMAND "${flags}")
run(${CXX} ${SOURCE_DIR}/tests/consumer/main.cpp ${flag_list} -o ${WORK_DIR}/consumer_pc)
run(${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${WORK_DIR}/prefix/lib ${WORK_DIR}/consumer_pc ${tablesdir})
