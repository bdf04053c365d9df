# The tree a submission is built in holds no test: pt-grade submission copies
# these items of the grading kit into it (autograder/submission/submission.cpp), and the
# submission's compiler may read all of them (an assembler .incbin), so
# pt-release-check must find in them no line of the solution's source and no
# hidden test's name. The graded tests live in the kit's verifiers/, outside.
#   cmake -DKIT=<grader-kit> -DOUT=<scratch> -DCHECK=<pt-release-check>
#         -DSOURCE=<checkout> -DMANIFEST=<graded_manifest.json> -P check_kit_tree.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
foreach(item CMakeLists.txt include lib src bin)
  file(COPY ${KIT}/${item} DESTINATION ${OUT})
endforeach()
file(GLOB tests_archives ${OUT}/lib/libpt_tests_part*.a)
if(tests_archives)
  message(FATAL_ERROR "the kit's lib/ holds tests: ${tests_archives}")
endif()
execute_process(COMMAND ${CHECK} --release ${OUT} --source ${SOURCE} --manifest ${MANIFEST} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pt-release-check found what a submission's build could read (above)")
endif()
