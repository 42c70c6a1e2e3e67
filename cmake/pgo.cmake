# Opt-in profile-guided optimisation, driven by scripts/build-pgo.sh: GENERATE instruments
# every object, a training run of the sweep writes one profile per object into
# SKINSIM_PGO_DIR, and USE compiles again with them (GCC's -fprofile-use: branch layout,
# inlining and unrolling chosen from measured counts). It changes no value the program
# computes: the compiler may not reassociate floating-point arithmetic without -ffast-math,
# and the baseline x86-64 target has no FMA to contract into (the golden tests run against
# the optimised binary; docs/performance.md has the measured gain).
set(SKINSIM_PGO OFF CACHE STRING "Profile-guided optimisation stage: OFF, GENERATE or USE")
set_property(CACHE SKINSIM_PGO PROPERTY STRINGS OFF GENERATE USE)
set(SKINSIM_PGO_DIR "${CMAKE_BINARY_DIR}/pgo-profile" CACHE PATH
    "Where GENERATE's training run writes the profiles and USE reads them")

if(NOT SKINSIM_PGO STREQUAL "OFF")
  if(NOT SKINSIM_PGO MATCHES "^(GENERATE|USE)$")
    message(FATAL_ERROR "SKINSIM_PGO=${SKINSIM_PGO}: expected OFF, GENERATE or USE")
  endif()
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "SKINSIM_PGO uses GCC's profile flags; the compiler is ${CMAKE_CXX_COMPILER_ID}")
  endif()
  if(SKINSIM_SANITIZE OR SKINSIM_TSAN)
    message(FATAL_ERROR "SKINSIM_PGO is for optimised builds: not together with the sanitizers")
  endif()
endif()

if(SKINSIM_PGO STREQUAL "GENERATE")
  add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:-fprofile-generate;-fprofile-dir=${SKINSIM_PGO_DIR}>")
  add_link_options(-fprofile-generate)
elseif(SKINSIM_PGO STREQUAL "USE")
  # -fprofile-partial-training: code the training did not run (tests, other techniques'
  # rarely used paths) is optimised as usual, not for size. -fprofile-correction: the
  # training's worker threads update counters without atomics, so counts may be slightly
  # inconsistent. Objects the training never loaded have no profile, which is expected.
  # -Wno-error=coverage-mismatch: a source edited after the training still compiles here
  # (GCC's default makes a stale profile an error), with a warning naming each function whose
  # profile it drops; scripts/build-pgo.sh trains afresh.
  add_compile_options(
    "$<$<COMPILE_LANGUAGE:CXX>:-fprofile-use;-fprofile-dir=${SKINSIM_PGO_DIR};-fprofile-partial-training;-fprofile-correction;-Wno-missing-profile;-Wno-error=coverage-mismatch>")
endif()
