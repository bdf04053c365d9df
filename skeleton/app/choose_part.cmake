# Which side of part PART a renderer links (cmake -P; the top-level
# CMakeLists, PT_REFERENCE_PARTS): the student's task file, or the course's
# solution while that file still throws NotImplemented in any task (CHOICE
# auto), or as the student chose (CHOICE yours|solution).
#   -DPART=<n> -DCHOICE=auto|yours|solution -DTASK_FILES=<a.cpp;...>
#   -DSTUDENT=<objects> -DSOLUTION=<objects or one archive> -DAR=<ar>
#   -DARCHIVE=<out .a> -DHEADER=<out .h, rewritten only when it changes>
cmake_minimum_required(VERSION 3.22)
set(side ${CHOICE})
if(CHOICE STREQUAL "auto")
  set(side yours)
  foreach(f IN LISTS TASK_FILES)
    file(READ ${f} text)
    # A commented-out throw is not one: comments off first.
    string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" text "${text}")
    string(REGEX REPLACE "//[^\n]*" "" text "${text}")
    if(text MATCHES "throw[ \t\r\n]+(pt::)?NotImplemented")
      set(side solution)
    endif()
  endforeach()
endif()
if(side STREQUAL "solution" AND NOT SOLUTION)
  set(side yours)  # a tree without the solution has only the student's side
endif()

file(REMOVE ${ARCHIVE})
if(side STREQUAL "yours")
  set(objects ${STUDENT})
else()
  set(objects ${SOLUTION})
endif()
if(objects MATCHES "\\.a$")
  file(COPY_FILE ${objects} ${ARCHIVE})
else()
  execute_process(COMMAND ${AR} qc ${ARCHIVE} ${objects} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "choose_part.cmake: ${AR} failed for part ${PART}")
  endif()
endif()

if(side STREQUAL "yours")
  set(digit "${PART}")
else()
  set(digit "")
endif()
file(CONFIGURE OUTPUT ${HEADER} CONTENT "#define PT_PART${PART}_FROM_TASKS \"${digit}\"\n")
