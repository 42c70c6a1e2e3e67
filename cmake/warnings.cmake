# Warnings as an interface target every project library links.
add_library(skinsim_warnings INTERFACE)
target_compile_options(skinsim_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough>)
