# Concatenates the graded-test listings (--pt_list_graded, one JSON object per
# line) of the all-reference test binaries into one manifest.
#   cmake -DOUT=<file> -DBINARIES=<bin;bin;...> -P manifest.cmake
set(text "")
foreach(b IN LISTS BINARIES)
  execute_process(COMMAND ${b} --pt_list_graded OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "manifest.cmake: ${b} --pt_list_graded failed (${rc})")
  endif()
  string(APPEND text "${out}")
endforeach()
file(WRITE ${OUT}.tmp "${text}")
file(RENAME ${OUT}.tmp ${OUT})
