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
endif()
