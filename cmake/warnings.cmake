# Warnings as an interface target every project library links.
add_library(skinsim_warnings INTERFACE)
target_compile_options(skinsim_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough>)
if(SKINSIM_WERROR)
  target_compile_options(skinsim_warnings INTERFACE $<$<CXX_COMPILER_ID:GNU,Clang>:-Werror>)
  # GCC 12 reports -Wrestrict inside libstdc++'s std::string when inlining a plain string
  # assignment at -O2 (GCC bug 105329, a false positive): still shown, not fatal.
  target_compile_options(skinsim_warnings INTERFACE $<$<CXX_COMPILER_ID:GNU>:-Wno-error=restrict>)
  # Under the sanitizers' instrumentation at -O1 (scripts/test.sh), GCC 12 reports
  # -Wmaybe-uninitialized inside libstdc++'s std::regex and std::function moves, false
  # positives the Release build (-O2, no instrumentation) does not see; the Release build keeps
  # the warning fatal, so only the sanitizer build shows it without failing.
  if(SKINSIM_SANITIZE OR SKINSIM_TSAN)
    target_compile_options(skinsim_warnings INTERFACE
      $<$<CXX_COMPILER_ID:GNU>:-Wno-error=maybe-uninitialized>)
  endif()
endif()
