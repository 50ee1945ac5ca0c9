# Merges static archives into one (cmake -DAR=ar -DOUT=lib.a "-DARCHIVES=a.a;b.a" -P merge_archives.cmake):
# an MRI script for ar, members of every archive kept as they are.
set(script "create ${OUT}\n")
foreach(a ${ARCHIVES})
  string(APPEND script "addlib ${a}\n")
endforeach()
string(APPEND script "save\nend\n")
file(WRITE ${OUT}.mri "${script}")
file(REMOVE ${OUT})
execute_process(COMMAND ${AR} -M INPUT_FILE ${OUT}.mri RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ar -M could not merge the archives into ${OUT}: ${err}")
endif()
