# cmake -P: cmake/build_identity.cmake on a scratch tree of two "sources". The identity
# changes when a source's bytes or the compiler change, and an unchanged tree leaves the
# generated file untouched (so nothing is recompiled).
cmake_minimum_required(VERSION 3.20)
set(dir "${WORK_DIR}/build_identity")
file(REMOVE_RECURSE "${dir}")
file(WRITE "${dir}/src/a.cpp" "int a() { return 1; }\n")
file(WRITE "${dir}/src/b.h" "#pragma once\n")
file(WRITE "${dir}/list.txt" "src/a.cpp\nsrc/b.h\n")

function(identity compiler out)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${dir} -DFILE_LIST=${dir}/list.txt
    "-DCOMPILER=${compiler}" -DOUTPUT=${dir}/identity.cpp -P ${SCRIPT}
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "build_identity.cmake failed: ${rc}")
  endif()
  file(STRINGS "${dir}/identity.cpp" line REGEX "sha256:[0-9a-f]+")
  string(REGEX MATCH "sha256:[0-9a-f]+" id "${line}")
  string(LENGTH "${id}" length)
  if(NOT id MATCHES "^sha256:[0-9a-f]+$" OR NOT length EQUAL 23)
    message(FATAL_ERROR "no 16-digit identity in identity.cpp: '${line}'")
  endif()
  set(${out} "${id}" PARENT_SCOPE)
endfunction()

identity("GNU 12.2.0" first)
file(TIMESTAMP "${dir}/identity.cpp" written "%s")
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
identity("GNU 12.2.0" again)
file(TIMESTAMP "${dir}/identity.cpp" rewritten "%s")
if(NOT again STREQUAL first OR NOT rewritten STREQUAL written)
  message(FATAL_ERROR "same sources: ${first} then ${again}, file time ${written} then ${rewritten}")
endif()

file(APPEND "${dir}/src/b.h" "int b();\n")
identity("GNU 12.2.0" edited)
if(edited STREQUAL first)
  message(FATAL_ERROR "an edited source kept the identity ${first}")
endif()

identity("Clang 14.0.6" other_compiler)
if(other_compiler STREQUAL edited)
  message(FATAL_ERROR "another compiler kept the identity ${edited}")
endif()
file(REMOVE_RECURSE "${dir}")
message(STATUS "identities: ${first}, edited ${edited}, other compiler ${other_compiler}")
