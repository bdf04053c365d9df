# Writes the student release, the grading kit or a grader's export (cmake -P; see CMakeLists.txt).
#   -DMODE=student|kit|gradescope|prairielearn -DSOURCE_DIR=<checkout> -DBINARY_DIR=<build> -DOUT=<dir>
#   student only: -DMANIFEST=<graded_manifest.json> -DTHIRD_PARTY=<third_party.cmake's folder>
#   kit only: -DMANIFEST=<graded_manifest.json> -DPT_GRADE=<pt-grade> -DPT_LINK_GUARD=<pt-link-guard>
#             -DPT_LIBRARY_CHECK=<pt-library-check> -DPREBUILT=<the solution's libraries for this platform>
# Every file is chosen by an allowlist: what is not named here is not shipped.
cmake_minimum_required(VERSION 3.22)
foreach(v MODE SOURCE_DIR BINARY_DIR OUT)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "export.cmake: -D${v}=... is required")
  endif()
endforeach()

set(S ${SOURCE_DIR})
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# copy_tree(<dir relative to S> [EXCLUDE <regex>...]): every file below it,
# to the same place under OUT/${prefix}.
set(prefix "")
function(copy_tree rel)
  cmake_parse_arguments(ARG "" "" "EXCLUDE" ${ARGN})
  file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE ${S} ${S}/${rel}/*)
  foreach(f IN LISTS files)
    set(skip OFF)
    foreach(re IN LISTS ARG_EXCLUDE)
      if(f MATCHES "${re}")
        set(skip ON)
      endif()
    endforeach()
    if(NOT skip)
      get_filename_component(d ${f} DIRECTORY)
      file(COPY ${S}/${f} DESTINATION ${OUT}/${prefix}${d})
    endif()
  endforeach()
endfunction()

function(copy_file from to)
  get_filename_component(d ${OUT}/${to} DIRECTORY)
  file(MAKE_DIRECTORY ${d})
  file(COPY_FILE ${from} ${OUT}/${to})
endfunction()

# strip_debug(<file relative to OUT>): when -DOBJCOPY is given.
function(strip_debug rel)
  if(DEFINED OBJCOPY AND OBJCOPY)
    execute_process(COMMAND ${OBJCOPY} --strip-debug ${OUT}/${rel} RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "export.cmake: ${OBJCOPY} --strip-debug ${rel} failed")
    endif()
  endif()
endfunction()

# write_release_facts(): prebuilt/release.json, what `pt-grade check-submission`
# (autograder/submission/check_submission.h) compares a student's tree with: the task
# files' names, each part's hidden tests (how many, how many points: never
# their names) and the SHA-256 of every file the grader has its own copy of
# (the framework, the tests, the build), so that an edit is named.
function(write_release_facts)
  if(NOT DEFINED MANIFEST)
    message(FATAL_ERROR "export.cmake: MODE student needs -DMANIFEST=...")
  endif()
  file(READ ${MANIFEST} manifest)
  set(facts "{\"format\": \"pt release facts 1\", \"task_files\": {}, \"hidden\": {}, \"files\": {}}")
  file(GLOB tasks RELATIVE ${OUT}/tasks ${OUT}/tasks/part*.cpp)
  foreach(t IN LISTS tasks)
    string(REGEX MATCH "^part([0-9]+)_" _ ${t})
    string(JSON facts SET "${facts}" task_files ${CMAKE_MATCH_1} "\"${t}\"")
  endforeach()
  string(JSON nparts LENGTH "${manifest}" parts)
  math(EXPR last "${nparts} - 1")
  foreach(i RANGE ${last})
    string(JSON part MEMBER "${manifest}" parts ${i})
    string(JSON ntests LENGTH "${manifest}" parts ${part})
    set(count 0)
    set(points 0)
    math(EXPR tlast "${ntests} - 1")
    foreach(j RANGE ${tlast})
      string(JSON visibility GET "${manifest}" parts ${part} ${j} visibility)
      if(visibility STREQUAL "hidden")
        string(JSON p GET "${manifest}" parts ${part} ${j} points)
        # An extension test is worth 0 unless the instructor counts it, and
        # check-submission shows it as the grader does by default.
        string(JSON extension ERROR_VARIABLE no_extension GET "${manifest}" parts ${part} ${j} extension)
        if(NOT no_extension AND extension)
          set(p 0)
        endif()
        math(EXPR count "${count} + 1")
        # cmake's math is integer only: points are added in hundredths.
        if(NOT p MATCHES "^([0-9]+)(\\.([0-9]?[0-9]?)0*)?$")
          message(FATAL_ERROR "export.cmake: ${part}: points '${p}' are not a multiple of 0.01")
        endif()
        set(whole ${CMAKE_MATCH_1})
        set(frac "${CMAKE_MATCH_3}00")
        string(SUBSTRING "${frac}" 0 2 frac)
        string(REGEX REPLACE "^0(.)" "\\1" frac "${frac}")
        math(EXPR points "${points} + ${whole} * 100 + ${frac}")
      endif()
    endforeach()
    string(JSON facts SET "${facts}" hidden ${part} "{\"tests\": ${count}, \"hundredths_of_points\": ${points}}")
  endforeach()
  file(GLOB_RECURSE shipped RELATIVE ${OUT} ${OUT}/skeleton/* ${OUT}/tests/* ${OUT}/prebuilt/*.a ${OUT}/cmake/*)
  list(APPEND shipped CMakeLists.txt CMakePresets.json)
  list(SORT shipped)
  foreach(f IN LISTS shipped)
    file(SHA256 ${OUT}/${f} hash)
    string(JSON facts SET "${facts}" files "${f}" "\"${hash}\"")
  endforeach()
  file(WRITE ${OUT}/prebuilt/release.json "${facts}\n")
endfunction()

# Scenes and their reference images go to both: students compare with them,
# the grader's report shows them.
set(scene_excludes "/build/" "\\.blend1?$")

# without_presets_named(<json variable> <name>): every preset of that name
# removed (the release has no tests/fuzz/ for the fuzz preset to build).
function(without_presets_named var name)
  set(doc "${${var}}")
  foreach(kind configurePresets buildPresets testPresets workflowPresets)
    string(JSON n ERROR_VARIABLE none LENGTH "${doc}" ${kind})
    if(none OR n EQUAL 0)
      continue()
    endif()
    math(EXPR i "${n} - 1")
    while(i GREATER_EQUAL 0)
      string(JSON preset GET "${doc}" ${kind} ${i} name)
      if(preset STREQUAL name)
        string(JSON doc REMOVE "${doc}" ${kind} ${i})
      endif()
      math(EXPR i "${i} - 1")
    endwhile()
  endforeach()
  set(${var} "${doc}" PARENT_SCOPE)
endfunction()

# without_provenance(<folder relative to OUT>): each image sidecar (*.json)
# without "git": the instructor's commit hashes stay at home.
function(without_provenance rel)
  file(GLOB sidecars ${OUT}/${rel}/*.json)
  foreach(f IN LISTS sidecars)
    file(READ ${f} doc)
    string(JSON doc ERROR_VARIABLE none REMOVE "${doc}" git)
    if(NOT none)
      file(WRITE ${f} "${doc}\n")
    endif()
  endforeach()
endfunction()

# without_instructor_notes(): every .md under OUT without the passages between
# "<!-- instructors -->" and "<!-- /instructors -->" (each marker on a line of
# its own): what only an instructor's checkout can run or needs to know.
function(without_instructor_notes)
  file(GLOB_RECURSE docs ${OUT}/*.md)
  foreach(f IN LISTS docs)
    file(READ ${f} text)
    set(changed OFF)
    while(TRUE)
      string(FIND "${text}" "<!-- instructors -->\n" start)
      if(start EQUAL -1)
        break()
      endif()
      string(FIND "${text}" "<!-- /instructors -->\n" end)
      if(end LESS start)
        message(FATAL_ERROR "export.cmake: ${f}: an instructors' passage without its end marker")
      endif()
      math(EXPR after "${end} + 22")
      string(SUBSTRING "${text}" 0 ${start} before)
      string(SUBSTRING "${text}" ${after} -1 rest)
      set(text "${before}${rest}")
      set(changed ON)
    endwhile()
    if(changed)
      file(WRITE ${f} "${text}")
    endif()
  endforeach()
endfunction()

# copy_course_repository(): the instructor's whole repository, the solution
# included, under OUT/pathtracer/: what a grader's image builds its kit from
# (autograder/build_grader_image.sh).
macro(copy_course_repository)
  set(prefix pathtracer/)
  foreach(f CMakeLists.txt CMakePresets.json setup.sh .gitignore)
    copy_file(${S}/${f} ${prefix}${f})
  endforeach()
  foreach(d cmake skeleton tasks reference tests autograder scenes handouts tools)  # tools/: the root CMakeLists adds it
    copy_tree(${d} EXCLUDE ${scene_excludes})
  endforeach()
endmacro()

if(MODE STREQUAL "student")
  copy_file(${S}/tools/release/README.student.md README.md)
  foreach(f CMakeLists.txt setup.sh .gitignore cmake/dependencies.cmake .devcontainer/devcontainer.json)
    copy_file(${S}/${f} ${f})
  endforeach()
  # The third-party code a build uses where the system has none
  # (third_party.cmake made it from this machine's Debian packages).
  if(NOT DEFINED THIRD_PARTY OR NOT EXISTS ${THIRD_PARTY}/README.md)
    message(FATAL_ERROR "export.cmake: MODE student needs -DTHIRD_PARTY=<third_party.cmake's folder>")
  endif()
  file(COPY ${THIRD_PARTY}/ DESTINATION ${OUT}/third_party)
  # Pushed as a GitHub Classroom template repository, the release grades each
  # push with its visible tests (github-classroom/, docs/instructors.md).
  copy_file(${S}/tools/release/github-classroom/classroom.yml .github/workflows/classroom.yml)
  copy_file(${S}/tools/release/github-classroom/grade.sh .github/classroom/grade.sh)
  file(READ ${S}/CMakePresets.json presets)
  without_presets_named(presets fuzz)
  file(WRITE ${OUT}/CMakePresets.json "${presets}\n")
  copy_tree(skeleton)
  copy_tree(tasks)
  copy_tree(scenes EXCLUDE ${scene_excludes})
  without_provenance(scenes/reference)
  copy_tree(handouts)
  file(COPY ${S}/tests/CMakeLists.txt DESTINATION ${OUT}/tests)
  # Test support, except what ships compiled (support/compiled/).
  copy_tree(tests/support EXCLUDE "^tests/support/compiled/")
  # Visible graded tests only: tests/partN/hidden/ stays with the instructor.
  foreach(n 1 2 3 4 5)
    copy_tree(tests/part${n} EXCLUDE "/hidden/")
  endforeach()
  copy_tree(tests/framework)
  copy_tree(tests/cli)
  copy_tree(tests/viewer EXCLUDE "/node_modules/")
  # The grader, for `pt-grade run` on the student's own machine; not the
  # instructor's threat model, kit or Gradescope packaging.
  copy_tree(autograder EXCLUDE "^autograder/(kit|gradescope|prairielearn|hostile)/" "^autograder/README\\.md$"
            "^autograder/(build_grader_image|grading_args)\\.sh$"
            "^autograder/report/(test_report|test_leaderboard)\\.sh$"
            "^autograder/report/check_leaderboard\\.cmake$" "^autograder/report/browser/")
  # The benchmark, without the ladder of traversals from the reference to Embree.
  copy_tree(tools/bench EXCLUDE "/ladder\\.(h|cpp)$")
  # The generator of the library's procedural scene (the library tests render
  # it); not the reference images' renderer, which needs reference/.
  copy_file(${S}/tools/CMakeLists.txt tools/CMakeLists.txt)
  copy_file(${S}/tools/procedural_mesh.cpp tools/procedural_mesh.cpp)
  # The solution, compiled only: a folder per platform (README.prebuilt.md).
  file(GLOB libs RELATIVE ${BINARY_DIR}/prebuilt ${BINARY_DIR}/prebuilt/*-*-*/*.a)
  foreach(lib IN LISTS libs)
    copy_file(${BINARY_DIR}/prebuilt/${lib} prebuilt/${lib})
  endforeach()
  copy_file(${S}/tools/release/README.prebuilt.md prebuilt/README.md)
  without_instructor_notes()
  write_release_facts()
elseif(MODE STREQUAL "kit")
  foreach(v MANIFEST PT_GRADE PT_LINK_GUARD PT_LIBRARY_CHECK PREBUILT)
    if(NOT DEFINED ${v})
      message(FATAL_ERROR "export.cmake: MODE kit needs -D${v}=...")
    endif()
  endforeach()
  copy_file(${S}/autograder/kit/CMakeLists.txt CMakeLists.txt)
  copy_file(${S}/autograder/kit/README.md README.md)
  # Headers a task file may include, and nothing else of the framework's source.
  file(GLOB_RECURSE headers RELATIVE ${S}/skeleton ${S}/skeleton/*.h)
  foreach(h IN LISTS headers)
    copy_file(${S}/skeleton/${h} include/${h})
  endforeach()
  copy_file(${S}/skeleton/app/main.cpp src/main.cpp)
  copy_file(${S}/autograder/compile/header_probe.cpp src/header_probe.cpp)
  copy_tree(tasks)
  copy_tree(scenes EXCLUDE ${scene_excludes})
  copy_tree(handouts)  # the report sends each failure to its section
  copy_file(${MANIFEST} manifest.json)
  copy_file(${PT_GRADE} bin/pt-grade)
  copy_file(${PT_LINK_GUARD} bin/pt-link-guard)
  copy_file(${PT_LIBRARY_CHECK} bin/pt-library-check)
  foreach(tool pt-grade pt-link-guard pt-library-check)  # the grader's tools need no debug information either
    strip_debug(bin/${tool})
  endforeach()
  # The verifiers of the boundary's parts (autograder/boundary/README.md):
  # outside lib/ and src/, which a submission's tree copies and its build reads.
  if(DEFINED VERIFIERS AND VERIFIERS)
    string(REPLACE "," ";" verifiers "${VERIFIERS}")
    foreach(v IN LISTS verifiers)
      get_filename_component(name ${v} NAME)
      copy_file(${v} verifiers/${name})
      strip_debug(verifiers/${name})
      # Execute-only for others: a worker running as another user (nobody,
      # when the grader is root) cannot read the hidden tests in it, even
      # without Landlock.
      file(CHMOD ${OUT}/verifiers/${name} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_EXECUTE WORLD_EXECUTE)
    endforeach()
  endif()
  copy_file(${BINARY_DIR}/grader-kit-lib/test_main.o lib/test_main.o)
  file(GLOB libs ${BINARY_DIR}/grader-kit-lib/*.a ${PREBUILT}/libpt_part*_reference.a)
  foreach(lib IN LISTS libs)
    get_filename_component(name ${lib} NAME)
    # A boundary part's tests are only in its verifier: its tests' archive,
    # hidden tests included, has no place in a tree that hostile code builds in.
    if(name MATCHES "^libpt_tests_part([0-9]+)\\.a$")
      if(EXISTS ${BINARY_DIR}/grader-kit-lib/libpt_boundary_worker_part${CMAKE_MATCH_1}.a)
        continue()
      endif()
    endif()
    copy_file(${lib} lib/${name})
    # Without debug information the kit is a tenth of the size: a submission's
    # copy of it and its links are that much faster.
    strip_debug(lib/${name})
  endforeach()
elseif(MODE STREQUAL "gradescope")
  # Gradescope's autograder.zip: its two scripts at the top, the course's
  # repository (the solution included: the zip is the instructor's) below.
  foreach(f setup.sh run_autograder README.md)
    copy_file(${S}/autograder/gradescope/${f} ${f})
  endforeach()
  copy_course_repository()
elseif(MODE STREQUAL "prairielearn")
  # PrairieLearn's grader image: the Dockerfile at the top of the build
  # context, the course's repository below (its entry point is in it).
  foreach(f Dockerfile README.md)
    copy_file(${S}/autograder/prairielearn/${f} ${f})
  endforeach()
  copy_course_repository()
else()
  message(FATAL_ERROR "export.cmake: MODE must be student, kit, gradescope or prairielearn, not '${MODE}'")
endif()

if(DEFINED ARCHIVE AND MODE STREQUAL "gradescope")
  # Gradescope wants setup.sh and run_autograder at the top of the zip.
  execute_process(COMMAND ${CMAKE_COMMAND} -E tar cf ${ARCHIVE} --format=zip setup.sh run_autograder README.md pathtracer
                  WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "export.cmake: could not write ${ARCHIVE}")
  endif()
elseif(DEFINED ARCHIVE)
  get_filename_component(parent ${OUT} DIRECTORY)
  get_filename_component(name ${OUT} NAME)
  # Relative paths, so the archive unpacks into one folder of that name.
  execute_process(COMMAND ${CMAKE_COMMAND} -E tar czf ${ARCHIVE} ${name} WORKING_DIRECTORY ${parent}
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "export.cmake: could not write ${ARCHIVE}")
  endif()
endif()
