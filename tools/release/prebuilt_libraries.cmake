# pt_prebuilt_libraries(<checkout> <folder> <targets variable>): the solution
# compiled only, into <folder>: one static library per part
# (libpt_partN_reference.a) and the near-solution test support
# (libpt_test_compiled.a); the targets' names go to <targets variable>. Needs
# the targets pt_skeleton, GTest::gtest and Boost::headers (for their headers
# and settings only). Used by the instructor's build for its own platform
# (CMakeLists.txt beside this file) and by its build of the libc++ variant
# (prebuilt/CMakeLists.txt).
function(pt_prebuilt_libraries checkout dir targets_var)
  set(targets "")
  foreach(n 1 2 3 4 5)
    file(GLOB src CONFIGURE_DEPENDS ${checkout}/reference/part${n}_*.cpp)
    add_library(pt_prebuilt_part${n} STATIC ${src})
    target_link_libraries(pt_prebuilt_part${n} PRIVATE pt_skeleton)
    set_target_properties(pt_prebuilt_part${n} PROPERTIES OUTPUT_NAME pt_part${n}_reference)
    list(APPEND targets pt_prebuilt_part${n})
  endforeach()
  file(GLOB compiled_support CONFIGURE_DEPENDS ${checkout}/tests/support/compiled/*.cpp)
  add_library(pt_prebuilt_test_compiled STATIC ${compiled_support})
  # Only its own objects: linking the support (an object library) would copy
  # the support's objects into this archive too; GoogleTest's headers, not its library.
  target_include_directories(pt_prebuilt_test_compiled PRIVATE ${checkout}/tests
                             $<TARGET_PROPERTY:GTest::gtest,INTERFACE_INCLUDE_DIRECTORIES>)
  target_link_libraries(pt_prebuilt_test_compiled PRIVATE pt_skeleton Boost::headers)
  set_target_properties(pt_prebuilt_test_compiled PROPERTIES OUTPUT_NAME pt_test_compiled)
  list(APPEND targets pt_prebuilt_test_compiled)
  foreach(t IN LISTS targets)
    # -g0: no debug information, so no source lines; strip -x: no local symbols
    # (a helper's name, Builder::best_split, says how the solution works), only
    # the global ones the linker needs. pt-release-check fails on any left.
    target_compile_options(${t} PRIVATE -g0)
    add_custom_command(TARGET ${t} POST_BUILD COMMAND ${CMAKE_STRIP} -x $<TARGET_FILE:${t}> VERBATIM)
    set_target_properties(${t} PROPERTIES ARCHIVE_OUTPUT_DIRECTORY ${dir})
  endforeach()
  set(${targets_var} ${targets} PARENT_SCOPE)
endfunction()
