# to_hundredths(<points> <out>): a number of points in hundredths, for the
# release tests' checks of results (expect_score.cmake,
# github-classroom/check_result.cmake). CMake's arithmetic is integer; points
# are multiples of 0.5 (0.25 at the finest).
function(to_hundredths value out)
  if(NOT value MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "${value} is not a number of points")
  endif()
  set(whole ${CMAKE_MATCH_1})
  string(SUBSTRING "${CMAKE_MATCH_3}00" 0 2 frac)
  math(EXPR h "${whole} * 100 + ${frac}")
  set(${out} ${h} PARENT_SCOPE)
endfunction()
