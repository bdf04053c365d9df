# The student release's third_party/ (cmake -P; tools/release/CMakeLists.txt):
# the third-party code a release build needs where the student's system has
# none (cmake/dependencies.cmake uses it), copied from the Debian packages this
# machine has, each with the package's copyright file (which names its
# licences) and version, as dpkg reports them. Never committed: made again
# whenever the packages change.
#   -DOUT=<folder>
# Header-only libraries go whole (their include folder); the single-header
# ones whose implementation the release compiles from the header (tinyexr,
# tinyobjloader, stb) go as that header; Boost.Math as the subset that the
# test statistics include, extracted with Boost's own bcp (libboost-tools-dev),
# which follows every #include whatever the platform; GoogleTest as its source
# (Debian's googletest package), which the release builds where the system has
# no GoogleTest built for its compiler.
cmake_minimum_required(VERSION 3.22)
if(NOT DEFINED OUT)
  message(FATAL_ERROR "third_party.cmake: -DOUT=<folder> is required")
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

set(table "")
# ship(<folder> <what it is for> <file or folder>... [TO <subfolder>]
#      [PACKAGE_OF <file>]): copies each path into <folder>/<subfolder> (default
# include), with the copyright file and the version of the Debian package that
# holds the first path (or PACKAGE_OF's file).
function(ship folder purpose)
  cmake_parse_arguments(ARG "" "TO;PACKAGE_OF" "" ${ARGN})
  if(NOT DEFINED ARG_TO)
    set(ARG_TO include)
  endif()
  list(GET ARG_UNPARSED_ARGUMENTS 0 first)
  if(ARG_PACKAGE_OF)
    set(first ${ARG_PACKAGE_OF})
  endif()
  if(NOT EXISTS ${first})
    message(FATAL_ERROR "third_party.cmake: ${first} is missing: install the packages ./setup.sh lists")
  endif()
  execute_process(COMMAND dpkg-query -S ${first} OUTPUT_VARIABLE owner RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "third_party.cmake: no Debian package holds ${first}")
  endif()
  string(REGEX REPLACE "^([^:]+).*" "\\1" package "${owner}")
  execute_process(COMMAND dpkg-query -W -f=\${Version} ${package} OUTPUT_VARIABLE version RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "third_party.cmake: dpkg-query could not tell ${package}'s version")
  endif()
  file(MAKE_DIRECTORY ${OUT}/${folder}/${ARG_TO})
  foreach(path IN LISTS ARG_UNPARSED_ARGUMENTS)
    file(COPY ${path} DESTINATION ${OUT}/${folder}/${ARG_TO})
  endforeach()
  file(COPY_FILE /usr/share/doc/${package}/copyright ${OUT}/${folder}/copyright)
  file(WRITE ${OUT}/${folder}/version "${package} ${version}\n")
  set(table "${table}| `${folder}/` | ${purpose} | ${package} | ${version} |\n" PARENT_SCOPE)
endfunction()

ship(glm "vectors and matrices (everywhere)" /usr/include/glm)
ship(nlohmann-json "JSON: scenes, results" /usr/include/nlohmann)
ship(CLI11 "command lines" /usr/include/CLI)
ship(pcg "the framework's random numbers" /usr/include/pcg_random.hpp /usr/include/pcg_extras.hpp
     /usr/include/pcg_uint128.hpp)
ship(stb "PNG reading and writing" /usr/include/stb/stb_image.h /usr/include/stb/stb_image_write.h TO include/stb)
ship(tinyexr "EXR images" /usr/include/tinyexr.h)
ship(tinyobjloader "OBJ meshes" /usr/include/tiny_obj_loader.h)

# Boost.Math's distributions (tests/support/statistics.cpp), with what they
# include. bcp copies every file it can reach below the root it is given; with
# /usr/include as the root that includes the C library's headers too, which
# are dropped: only boost/ is kept (one header includes "../include/fenv.h",
# which bcp writes beside its output folder: both are in .bcp/).
find_program(BCP bcp)
if(NOT BCP)
  message(FATAL_ERROR "third_party.cmake: bcp (libboost-tools-dev) is needed to extract Boost.Math's subset: "
                      "install the packages ./setup.sh lists")
endif()
set(bcp_out ${OUT}/.bcp/out)
file(MAKE_DIRECTORY ${bcp_out})
execute_process(COMMAND ${BCP} --boost=/usr/include boost/math/distributions/chi_squared.hpp
                        boost/math/distributions/normal.hpp boost/math/distributions/students_t.hpp ${bcp_out}
                OUTPUT_QUIET ERROR_VARIABLE bcp_errors RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT EXISTS ${bcp_out}/boost/math/distributions/students_t.hpp)
  message(FATAL_ERROR "third_party.cmake: bcp failed: ${bcp_errors}")
endif()
ship(boost "Boost.Math's distributions (the tests' statistics)" ${bcp_out}/boost
     PACKAGE_OF /usr/include/boost/math/distributions/normal.hpp)
file(REMOVE_RECURSE ${OUT}/.bcp)

# GoogleTest's source: its build files and the library, not its own tests,
# samples, documentation or Google Mock (not used here).
ship(googletest "GoogleTest, built from source" /usr/src/googletest/CMakeLists.txt TO .)
foreach(d cmake include src)
  file(COPY /usr/src/googletest/googletest/${d} DESTINATION ${OUT}/googletest/googletest)
endforeach()
file(COPY /usr/src/googletest/googletest/CMakeLists.txt DESTINATION ${OUT}/googletest/googletest)

file(WRITE ${OUT}/README.md "# third_party/

The third-party code this release builds with where your system has none:
copied, unmodified, from the Debian packages of the machine that made the
release. Each folder holds the package's `copyright` file (its licences) and
its `version`. The build uses your system's packages when it finds them and
these copies otherwise; `cmake --preset default -DPT_SYSTEM_DEPS=OFF` uses only
these.

| folder | for | Debian package | version |
|---|---|---|---|
${table}
Not here, because Debian ships no source for them: pugixml (COLLADA `.dae`
scenes) and cpp-httplib (the viewer, `pathtracer --view`). Without them the
build leaves those two out and says so; each is one package to install
(README.md, \"Set up\").
")
