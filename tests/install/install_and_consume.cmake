# Installs the build tree into a staging prefix, then configures, builds and runs a tiny
# downstream project that finds the package there (find_package(lbdem)).
# Arguments: BUILD, STAGE, SOURCE (the consumer project), WORK, CXX, LAUNCHER (may be empty).
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${STAGE} ${WORK})
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${STAGE})
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK} -DCMAKE_PREFIX_PATH=${STAGE}
    -DCMAKE_CXX_COMPILER=${CXX} ${launcher})
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK})
run("running the consumer" ${WORK}/consumer)
message("${last_output}")
