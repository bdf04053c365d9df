# A tasks/ of any content configures (cmake -P; hostile:configure-any-tasks):
# tasks/ is the student's, and may hold a solution installed as the student's
# file, a new stub or text that is no C++ at all. The checkout is seen through
# a scratch tree of links, its tasks/ replaced by such files, and configured
# in a build folder of its own; no file of the hostile gallery may hold their
# text (a case made from tasks/ would).
#   -DSOURCE=<checkout> -DWORK=<scratch folder> -DGENERATOR=<cmake generator>
cmake_minimum_required(VERSION 3.22)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/src/tasks)
file(GLOB entries RELATIVE ${SOURCE} ${SOURCE}/*)
foreach(entry IN LISTS entries)
  if(NOT entry STREQUAL "tasks" AND NOT entry MATCHES "^(build|\\.git$)")
    file(CREATE_LINK ${SOURCE}/${entry} ${WORK}/src/${entry} SYMBOLIC)
  endif()
endforeach()

set(marker "pt-configure-any-tasks: text of the student's own")
file(GLOB stubs RELATIVE ${SOURCE}/tasks ${SOURCE}/tasks/part*_*.cpp)
foreach(name IN LISTS stubs)
  if(name MATCHES "^part1_")  # not C++ at all
    file(WRITE ${WORK}/src/tasks/${name} "${marker}\n")
  elseif(name MATCHES "^part([0-9]+)_")  # the solution, installed as the student's file
    file(READ ${SOURCE}/reference/${name} text)
    file(WRITE ${WORK}/src/tasks/${name} "// ${marker}\n${text}")
  endif()
endforeach()

string(TIMESTAMP start "%s")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK}/src -B ${WORK}/build -G ${GENERATOR}
                        -DCMAKE_BUILD_TYPE=RelWithDebInfo
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(TIMESTAMP end "%s")
math(EXPR seconds "${end} - ${start}")
message(STATUS "configured in about ${seconds} s")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "a tasks/ of other content does not configure:\n${err}")
endif()
file(GLOB_RECURSE generated ${WORK}/build/autograder/hostile/*.cpp)
if(NOT generated)
  message(FATAL_ERROR "no hostile case was generated: is this an instructor's checkout?")
endif()
foreach(f IN LISTS generated)
  file(STRINGS ${f} hits REGEX "pt-configure-any-tasks")
  if(hits)
    message(FATAL_ERROR "${f} was made from tasks/: a hostile case must not change with the student's file")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
