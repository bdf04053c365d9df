# Adds the solution's libraries for another platform, compiled on a machine of
# that platform (a Mac: docs/instructors.md, "The release on a Mac"), to the
# student release this checkout's build exports:
#   cmake -DLIBRARIES=<folder> -DBUILD=<build folder> -P tools/release/add_prebuilt.cmake
#   cmake --build --preset default --target student-release
# <folder> is what tools/release/prebuilt/ wrote on that machine,
# build-prebuilt/prebuilt/<os>-<arch>-<standard library>/, under that name. It is
# kept in <build>/prebuilt/ beside this machine's own, and every later export
# ships it, until it is removed from there or the build folder is.
cmake_minimum_required(VERSION 3.22)
foreach(v LIBRARIES BUILD)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "add_prebuilt.cmake: -D${v}=... is required")
  endif()
endforeach()
get_filename_component(platform ${LIBRARIES} NAME)
if(NOT platform MATCHES "^[a-z]+-[a-z0-9_]+-lib(c|stdc)\\+\\+$")
  message(FATAL_ERROR "add_prebuilt.cmake: ${LIBRARIES}: the folder must be named <os>-<arch>-<standard library> "
                      "(e.g. macos-arm64-libc++), as tools/release/prebuilt/ names it")
endif()
set(names libpt_part1_reference.a libpt_part2_reference.a libpt_part3_reference.a libpt_part4_reference.a
          libpt_part5_reference.a libpt_test_compiled.a)
foreach(name IN LISTS names)
  set(lib ${LIBRARIES}/${name})
  if(NOT EXISTS ${lib})
    message(FATAL_ERROR "add_prebuilt.cmake: ${lib} is missing (each of: ${names})")
  endif()
  file(READ ${lib} magic LIMIT 8)
  if(NOT magic STREQUAL "!<arch>\n")
    message(FATAL_ERROR "add_prebuilt.cmake: ${lib} is not a static library")
  endif()
endforeach()
file(GLOB others RELATIVE ${LIBRARIES} ${LIBRARIES}/*)
list(REMOVE_ITEM others ${names})
if(others)
  message(FATAL_ERROR "add_prebuilt.cmake: ${LIBRARIES} holds more than the six libraries: ${others}")
endif()
if(NOT EXISTS ${BUILD}/student-release.tar.gz AND NOT EXISTS ${BUILD}/CMakeCache.txt)
  message(FATAL_ERROR "add_prebuilt.cmake: ${BUILD} is not this checkout's build folder")
endif()
file(REMOVE_RECURSE ${BUILD}/prebuilt/${platform})
file(COPY ${LIBRARIES}/ DESTINATION ${BUILD}/prebuilt/${platform})
# The export runs again at the next build (its archive is its output).
file(REMOVE ${BUILD}/student-release.tar.gz)
message(STATUS "prebuilt/${platform}/ added: the next build of student-release ships it "
               "(pt-release-check checks it as it checks this platform's)")
