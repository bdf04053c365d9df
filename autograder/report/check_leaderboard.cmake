# The checks of test_leaderboard.sh on the four results.json it wrote under WORK.
#   cmake -DWORK=<folder> -P check_leaderboard.cmake
cmake_minimum_required(VERSION 3.22)

function(fail what)
  message(FATAL_ERROR "${what}")
endfunction()

# board(<case> <prefix>): <prefix>_sah, <prefix>_tests, <prefix>_nodes from
# WORK/<case>/results.json's leaderboard, every entry checked for its fields.
function(board case prefix)
  file(READ ${WORK}/${case}/results.json doc)
  string(JSON n ERROR_VARIABLE missing LENGTH "${doc}" leaderboard)
  if(missing)
    fail("${case}: no leaderboard in results.json")
  endif()
  if(NOT n EQUAL 3)
    fail("${case}: ${n} leaderboard entries, expected 3")
  endif()
  foreach(i RANGE 2)
    string(JSON fields LENGTH "${doc}" leaderboard ${i})
    string(JSON name GET "${doc}" leaderboard ${i} name)
    string(JSON value GET "${doc}" leaderboard ${i} value)
    string(JSON type TYPE "${doc}" leaderboard ${i} value)
    string(JSON order GET "${doc}" leaderboard ${i} order)
    if(NOT fields EQUAL 3 OR NOT type STREQUAL "NUMBER" OR NOT order STREQUAL "asc")
      fail("${case}: entry ${i} (${name}) is not {name, value (a number), order asc}")
    endif()
    if(name STREQUAL "SAH cost / solution's")
      set(${prefix}_sah ${value} PARENT_SCOPE)
    elseif(name STREQUAL "Primitive tests per ray")
      set(${prefix}_tests ${value} PARENT_SCOPE)
    elseif(name STREQUAL "Node visits per ray")
      set(${prefix}_nodes ${value} PARENT_SCOPE)
    else()
      fail("${case}: an entry this test does not know: ${name}")
    endif()
  endforeach()
endfunction()

function(no_board case)
  file(READ ${WORK}/${case}/results.json doc)
  string(JSON n ERROR_VARIABLE missing LENGTH "${doc}" leaderboard)
  if(NOT missing)
    fail("${case}: results.json has a leaderboard")
  endif()
endfunction()

board(reference ref)
board(mutant mut)
# The solution's tree against itself: 1, up to the four digits kept.
if(ref_sah LESS 0.9995 OR ref_sah GREATER 1.0005)
  fail("reference: SAH cost / solution's is ${ref_sah}, not 1")
endif()
# Plausible work for a good tree on meshes and fibres, leaves of 4: a few
# leaves' primitives and a few dozen nodes per ray, never none.
if(ref_tests LESS 1 OR ref_tests GREATER 100 OR ref_nodes LESS 1 OR ref_nodes GREATER 200)
  fail("reference: ${ref_tests} primitive tests and ${ref_nodes} node visits per ray are not plausible")
endif()
# The mutant: 5.2x the baseline's cost on the fibres (tests/part2/test_bvh_build.cpp's
# table) and 1.06x on a mesh, about 2.3 as a geometric mean; 1.5 is far from both 1 and that.
if(NOT mut_sah GREATER 1.5)
  fail("mutant: SAH cost / solution's is ${mut_sah}, not worse than 1.5")
endif()
if(NOT mut_tests GREATER ref_tests)
  fail("mutant: ${mut_tests} primitive tests per ray, not more than the reference's ${ref_tests}")
endif()
no_board(plain)
no_board(stubs)
message(STATUS "leaderboard: reference ${ref_sah} / ${ref_tests} tests / ${ref_nodes} nodes per ray; "
               "single_axis_midpoint ${mut_sah} / ${mut_tests} / ${mut_nodes}; none without --leaderboard or a tree")
