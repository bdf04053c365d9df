# The third-party libraries. Each is the system's package when this build
# finds one it can link, else the copy the student release ships in
# third_party/: copied at export from the instructor's Debian packages, each
# with its Debian copyright file and version (third_party/README.md, written by
# tools/release/third_party.cmake). An instructor's checkout has no
# third_party/: there every package is the system's (setup.sh installs them).
#
#   -DPT_SYSTEM_DEPS=OFF  ignores the system's packages, so that only the
#                         shipped copies are used (the release's clang/libc++
#                         test, release:libcxx, configures with it).
#
# A compiled library (.so, .a) links only with the C++ standard library it was
# compiled against: Debian's with GCC's libstdc++. With clang's libc++ on
# Linux the shipped copies stand in for them; on macOS, Homebrew's are libc++.
#
# Two have no copy to ship (Debian's packages hold no source for them), and
# what needs them is left out, saying so, when they are missing:
#   pugixml      COLLADA (.dae) scenes: loading one says how to get it
#   cpp-httplib  the viewer: `pathtracer --view` says how to get it
option(PT_SYSTEM_DEPS "Use the system's third-party packages where found (OFF: only third_party/)" ON)
if(NOT DEFINED PT_THIRD_PARTY)  # the instructor's build of the libc++ solution names its own
  set(PT_THIRD_PARTY ${CMAKE_SOURCE_DIR}/third_party)
endif()

# The grader (pt-grade, autograder/) builds everywhere; its sandbox does not.
# PT_SANDBOX is the grader's Linux-only part: the sandbox's layers
# (namespaces, seccomp, Landlock: autograder/sandbox/), the grading kit's
# confined build and work area (compile/), the launcher's clone() and parent
# death signal (process/launcher_linux.cpp), the process boundary (boundary/,
# run/worker_run.cpp) and pt-link-guard (GNU nm on ELF objects). Off (macOS),
# pt-grade keeps check-submission: the files, the includes, each part built,
# the visible tests run as plain processes, and it says what only the grader
# checks; the commands that grade refuse, naming where to run them.
if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  option(PT_SANDBOX "Build the grader's sandbox, process boundary and link guard (Linux only)" ON)
else()
  set(PT_SANDBOX OFF)
endif()
option(PT_GRADER "Build the grader pt-grade (check-submission; grading too with PT_SANDBOX)" ON)
# pt-grade reads a zipped submission with libarchive: Debian's libarchive-dev
# (setup.sh), Homebrew's libarchive (keg-only: CMAKE_PREFIX_PATH names it).
# Without it a build without the sandbox (a student's Mac) leaves pt-grade out
# and says how to get it; the grader's own build (Linux) stops.
if(PT_GRADER AND NOT PT_PREBUILT_ONLY)
  find_package(LibArchive)
  if(NOT LibArchive_FOUND AND PT_SANDBOX)
    message(FATAL_ERROR "pt-grade needs libarchive (libarchive-dev: ./setup.sh installs it)")
  elseif(NOT LibArchive_FOUND)
    message(WARNING "pt-grade (check-submission) needs libarchive, which was not found: brew install libarchive, "
                    "then configure again with -DCMAKE_PREFIX_PATH=\"$(brew --prefix libarchive)\". Everything else "
                    "builds without it.")
    set(PT_GRADER OFF)
  endif()
endif()
if(NOT PT_PREBUILT_ONLY AND NOT PT_GRADER)  # PT_PREBUILT_ONLY: tools/release/prebuilt/
  message(WARNING "No grader in this build (PT_GRADER is off): ./build/tests/partN_tests runs each part's visible "
                  "tests, but pt-grade check-submission is not built.")
elseif(NOT PT_PREBUILT_ONLY AND NOT PT_SANDBOX)
  message(WARNING "No sandbox in this build (it needs Linux): pt-grade check-submission checks your files, builds "
                  "each part and runs its visible tests, and says what only the grader checks (the sandbox, the "
                  "process boundary, the link guard, the hidden tests). For the grader's own checks: WSL, the dev "
                  "container (.devcontainer/) or your course's GitHub Classroom run (README.md).")
endif()

include(CheckCXXSourceCompiles)
check_cxx_source_compiles("#include <cstddef>\n#ifndef _LIBCPP_VERSION\n#error libstdc++\n#endif\nint main() { return 0; }"
                          PT_LIBCXX)
set(PT_SYSTEM_LIBRARIES ${PT_SYSTEM_DEPS})
if(PT_LIBCXX AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
  set(PT_SYSTEM_LIBRARIES OFF)
endif()
# The same holds for the solution's prebuilt libraries, so the student release
# keeps one folder of them per platform, prebuilt/<os>-<arch>-<standard library>
# (tools/release/README.prebuilt.md): this build's name for its own.
if(CMAKE_SYSTEM_NAME STREQUAL "Darwin")
  set(pt_os macos)
else()
  string(TOLOWER "${CMAKE_SYSTEM_NAME}" pt_os)
endif()
string(TOLOWER "${CMAKE_SYSTEM_PROCESSOR}" pt_arch)
if(pt_arch STREQUAL "amd64")
  set(pt_arch x86_64)
elseif(pt_arch STREQUAL "aarch64")
  set(pt_arch arm64)
endif()
if(PT_LIBCXX)
  set(PT_PREBUILT_PLATFORM ${pt_os}-${pt_arch}-libc++)
else()
  set(PT_PREBUILT_PLATFORM ${pt_os}-${pt_arch}-libstdc++)
endif()

# pt_shipped(<target> <folder>): <target> from third_party/<folder>/include, or
# a stop that names what to install.
function(pt_shipped target folder)
  set(dir ${PT_THIRD_PARTY}/${folder}/include)
  if(NOT EXISTS ${dir})
    message(FATAL_ERROR "${folder} was not found: install it (./setup.sh does on Debian), or build the student "
                        "release, which ships it in third_party/")
  endif()
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${dir})
  set(PT_SHIPPED_USED ${PT_SHIPPED_USED} ${folder} PARENT_SCOPE)
endfunction()

# pt_shipped_compiled(<target> <folder> HEADERS <header>... DEFINES <macro>...):
# a single-header library, its implementation compiled here from its own
# headers with the macros that ask for it.
function(pt_shipped_compiled target folder)
  cmake_parse_arguments(ARG "" "" "HEADERS;DEFINES" ${ARGN})
  pt_shipped(${target}_headers ${folder})
  list(TRANSFORM ARG_DEFINES REPLACE "(.+)" "#define \\1\n")
  list(TRANSFORM ARG_HEADERS REPLACE "(.+)" "#include <\\1>\n")
  string(JOIN "" text ${ARG_DEFINES} ${ARG_HEADERS})
  file(CONFIGURE OUTPUT ${CMAKE_BINARY_DIR}/third_party/${folder}.cpp CONTENT "${text}")
  add_library(pt_shipped_${folder} STATIC EXCLUDE_FROM_ALL ${CMAKE_BINARY_DIR}/third_party/${folder}.cpp)
  target_link_libraries(pt_shipped_${folder} PUBLIC ${target}_headers)
  target_compile_options(pt_shipped_${folder} PRIVATE -w)
  add_library(${target} ALIAS pt_shipped_${folder})
  set(PT_SHIPPED_USED ${PT_SHIPPED_USED} ${folder} PARENT_SCOPE)
endfunction()

find_package(Threads REQUIRED)
set(PT_SHIPPED_USED "")
# Header-only: the system's whenever found.
if(PT_SYSTEM_DEPS)
  find_package(glm QUIET)
  find_package(nlohmann_json QUIET)
  find_package(CLI11 QUIET)
  find_path(PT_PCG_INCLUDE pcg_random.hpp)
  if(PT_BUILD_TESTS)
    find_package(Boost QUIET)  # header-only Boost.Math: tests/support/statistics.cpp
  endif()
endif()
if(NOT TARGET glm::glm)
  pt_shipped(glm::glm glm)
endif()
if(NOT TARGET nlohmann_json::nlohmann_json)
  pt_shipped(nlohmann_json::nlohmann_json nlohmann-json)
endif()
if(NOT TARGET CLI11::CLI11)
  pt_shipped(CLI11::CLI11 CLI11)
endif()
if(PT_PCG_INCLUDE)
  add_library(pcg::pcg INTERFACE IMPORTED GLOBAL)
  set_target_properties(pcg::pcg PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${PT_PCG_INCLUDE})
else()
  pt_shipped(pcg::pcg pcg)
endif()
if(PT_BUILD_TESTS AND NOT TARGET Boost::headers)
  pt_shipped(Boost::headers boost)
endif()

# Compiled: the system's only where it links with this standard library.
if(PT_SYSTEM_LIBRARIES)
  find_package(tinyexr QUIET)
  find_package(tinyobjloader QUIET)
  find_package(pugixml QUIET)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(STB QUIET IMPORTED_TARGET stb)
    pkg_check_modules(HTTPLIB QUIET IMPORTED_TARGET cpp-httplib)
  endif()
  if(PT_BUILD_TESTS)
    find_package(GTest QUIET)
  endif()
endif()
if(NOT TARGET tinyexr::tinyexr)
  find_package(ZLIB REQUIRED)  # tinyexr as Debian ships it compresses with zlib, not miniz
  pt_shipped_compiled(tinyexr::tinyexr tinyexr HEADERS tinyexr.h DEFINES TINYEXR_IMPLEMENTATION)
  target_link_libraries(pt_shipped_tinyexr PUBLIC ZLIB::ZLIB)
endif()
if(NOT TARGET tinyobjloader::tinyobjloader)
  pt_shipped_compiled(tinyobjloader::tinyobjloader tinyobjloader HEADERS tiny_obj_loader.h
                      DEFINES TINYOBJLOADER_IMPLEMENTATION)
endif()
add_library(stb::stb INTERFACE IMPORTED GLOBAL)  # stb_image and stb_image_write
if(TARGET PkgConfig::STB)
  set_target_properties(stb::stb PROPERTIES INTERFACE_LINK_LIBRARIES PkgConfig::STB)
else()
  pt_shipped_compiled(pt_stb stb HEADERS stb_image.h stb_image_write.h
                      DEFINES STB_IMAGE_IMPLEMENTATION STB_IMAGE_WRITE_IMPLEMENTATION)
  # Both spellings: <stb_image.h> (as pkg-config's -I.../stb has it) and <stb/stb_image.h>.
  set_property(TARGET pt_stb_headers APPEND PROPERTY INTERFACE_INCLUDE_DIRECTORIES ${PT_THIRD_PARTY}/stb/include/stb)
  set_target_properties(stb::stb PROPERTIES INTERFACE_LINK_LIBRARIES pt_stb)
endif()
if(PT_BUILD_TESTS AND NOT TARGET GTest::gtest)
  if(NOT EXISTS ${PT_THIRD_PARTY}/googletest/CMakeLists.txt)
    message(FATAL_ERROR "GoogleTest was not found: install it (./setup.sh does on Debian), or build the student "
                        "release, which ships its source in third_party/googletest/")
  endif()
  set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(${PT_THIRD_PARTY}/googletest ${CMAKE_BINARY_DIR}/third_party/googletest EXCLUDE_FROM_ALL)
  list(APPEND PT_SHIPPED_USED googletest)
endif()

# Optional: what needs them is left out, saying so.
if(TARGET pugixml::pugixml)
  set(PT_HAVE_COLLADA ON)
else()
  set(PT_HAVE_COLLADA OFF)
  message(STATUS "pugixml not found: no COLLADA (.dae) scenes in this build (JSON scenes only)")
endif()
if(TARGET PkgConfig::HTTPLIB)
  add_library(httplib::httplib INTERFACE IMPORTED GLOBAL)
  set_target_properties(httplib::httplib PROPERTIES INTERFACE_LINK_LIBRARIES PkgConfig::HTTPLIB)
elseif(PT_SYSTEM_LIBRARIES AND NOT TARGET httplib::httplib)
  find_package(httplib QUIET)  # Homebrew's cpp-httplib (header-only)
endif()
if(TARGET httplib::httplib)
  set(PT_HAVE_VIEWER ON)
else()
  set(PT_HAVE_VIEWER OFF)
  message(STATUS "cpp-httplib not found: no viewer in this build (pathtracer --view says so)")
endif()
if(PT_SHIPPED_USED)
  list(REMOVE_DUPLICATES PT_SHIPPED_USED)
  message(STATUS "Shipped third-party copies in use (third_party/): ${PT_SHIPPED_USED}")
endif()
