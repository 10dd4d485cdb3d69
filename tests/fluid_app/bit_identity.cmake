# Runs fluid_state_dump's two scenes on 1, 2 and 3 ranks (automatic grids, and forced grids
# that split x and y unevenly) and requires every dump to equal the scene's 1-rank dump byte
# for byte.
# Variables: MPIRUN (list: launcher and its options), EXE, WORK (scratch folder).
file(MAKE_DIRECTORY ${WORK})
set(cases "1:0:0:0" "2:0:0:0" "3:0:0:0" "2:2:1:1" "3:1:3:1" "3:3:1:1")
foreach(scene walls periodic)
  set(index 0)
  foreach(c IN LISTS cases)
    string(REPLACE ":" ";" c "${c}")
    list(GET c 0 np)
    list(GET c 1 dx)
    list(GET c 2 dy)
    list(GET c 3 dz)
    set(out ${WORK}/${scene}_${index}.bin)
    execute_process(COMMAND ${MPIRUN} -np ${np} ${EXE} ${scene} ${out} ${dx} ${dy} ${dz}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
    message("${scene}, np ${np} grid ${dx} ${dy} ${dz}: ${log}")
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "fluid_state_dump ${scene} failed on ${np} ranks (exit ${rc})")
    endif()
    if(index GREATER 0)
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${scene}_0.bin ${out}
                      RESULT_VARIABLE diff)
      if(NOT diff EQUAL 0)
        message(FATAL_ERROR
                "${scene}: state on ${np} ranks (grid ${dx} ${dy} ${dz}) differs from 1 rank")
      endif()
    endif()
    math(EXPR index "${index} + 1")
  endforeach()
endforeach()
message("all dumps are bit-identical")
