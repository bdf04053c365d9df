# Runs a command and checks how it ends: its exit status (a crash or a signal
# never passes) and its output. Used by the broken-input gallery (broken/).
#   cmake -DEXIT=2 -DEXPECT=<regex> [-DREJECT=<regex>] [-DSETUP=<kind>:<path>[:<size>]]
#         -P expect_exit.cmake -- <command> <args>...
# SETUP prepares an input too odd or too large to keep in the repository:
#   sparse:<path>:<size>  a file of <size> bytes that takes no disk (truncate)
#   loop:<path>           a symbolic link to itself
#   link:<path>:<target>  a symbolic link to <target>
#   dir:<path>            an empty directory
# and removes it afterwards.
set(command "")
set(after_dashes FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE 1 ${last})
  if(after_dashes)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(after_dashes TRUE)
  endif()
endforeach()
if(NOT command)
  message(FATAL_ERROR "expect_exit.cmake: no command after --")
endif()

set(made "")
if(SETUP)
  string(REPLACE ":" ";" setup "${SETUP}")
  list(GET setup 0 kind)
  list(GET setup 1 path)
  get_filename_component(parent "${path}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  file(REMOVE_RECURSE "${path}")
  if(kind STREQUAL "sparse")
    list(GET setup 2 size)
    execute_process(COMMAND truncate -s ${size} "${path}" RESULT_VARIABLE rv)
    if(NOT rv EQUAL 0)
      message(FATAL_ERROR "cannot make the sparse file ${path}")
    endif()
  elseif(kind STREQUAL "loop")
    get_filename_component(name "${path}" NAME)
    file(CREATE_LINK "${name}" "${path}" SYMBOLIC)  # relative: the link points at itself
  elseif(kind STREQUAL "link")
    list(GET setup 2 target)
    file(CREATE_LINK "${target}" "${path}" SYMBOLIC)
  elseif(kind STREQUAL "dir")
    file(MAKE_DIRECTORY "${path}")
  else()
    message(FATAL_ERROR "unknown SETUP kind ${kind}")
  endif()
  set(made "${path}")
endif()

execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(made)
  file(REMOVE_RECURSE "${made}")
endif()
set(output "${out}${err}")
string(REPLACE ";" " " shown "${command}")
message("$ ${shown}\n${output}")

if(NOT "${status}" STREQUAL "${EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXIT}")
endif()
if(DEFINED EXPECT AND NOT output MATCHES "${EXPECT}")
  message(FATAL_ERROR "the output does not match: ${EXPECT}")
endif()
if(DEFINED REJECT AND output MATCHES "${REJECT}")
  message(FATAL_ERROR "the output matches what it must not: ${REJECT}")
endif()
