# Fails unless a Gradescope results.json is what the untouched stubs earn:
# score 0, and every graded test failed with a message naming a task of its
# part ("not implemented: P2T1 ..." for a P2T3 test: its traversal needs a
# tree first), as pt-grade check-stubs asks.
#   cmake -DRESULTS=<results.json> -P expect_stubs.cmake
file(READ ${RESULTS} doc)
string(JSON score GET "${doc}" score)
if(NOT score MATCHES "^0(\\.0*)?$")
  message(FATAL_ERROR "${RESULTS}: the stubs scored ${score}, not 0")
endif()
string(JSON count LENGTH "${doc}" tests)
math(EXPR last "${count} - 1")
set(graded 0)
foreach(i RANGE ${last})
  string(JSON max GET "${doc}" tests ${i} max_score)
  if(max STREQUAL "0" OR max STREQUAL "0.0")
    continue()  # the instructor's zero-point entries
  endif()
  math(EXPR graded "${graded} + 1")
  string(JSON name GET "${doc}" tests ${i} name)
  string(JSON output GET "${doc}" tests ${i} output)
  string(REGEX MATCH "^P[0-9]+T" part_prefix "${name}")
  string(FIND "${output}" "not implemented: ${part_prefix}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${RESULTS}: ${name} does not fail with \"not implemented: ${part_prefix}...\":\n${output}")
  endif()
endforeach()
if(graded EQUAL 0)
  message(FATAL_ERROR "${RESULTS}: no graded test")
endif()
message(STATUS "${RESULTS}: 0 points, all ${graded} graded tests fail naming a task of their part")
