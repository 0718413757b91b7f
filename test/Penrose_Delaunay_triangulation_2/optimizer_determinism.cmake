# Regenerates a small correction table twice; both runs must agree, and the
# table must hold corrections (not only zeros).
foreach(run a b)
  execute_process(COMMAND ${OPTIMIZER} --bins 3 --points 2000 --iterations 5 --runs-per-bin 1
                          --out ${WORK}/table_${run}.h
                  RESULT_VARIABLE rc ERROR_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "optimizer failed (${rc})")
  endif()
endforeach()
file(READ ${WORK}/table_a.h a)
file(READ ${WORK}/table_b.h b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "two runs of the optimizer wrote different tables")
endif()
string(REGEX MATCHALL "-?0\\.[0-9]*[1-9][0-9]*f" nonzero "${a}")
list(LENGTH nonzero n)
if(n LESS 20)
  message(FATAL_ERROR "the table has only ${n} non-zero entries")
endif()
