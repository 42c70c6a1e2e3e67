# Opt-in ASan + UBSan: cmake -DSKINSIM_SANITIZE=ON (CI runs the unit tests this way).
if(SKINSIM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
# Opt-in ThreadSanitizer: cmake -DSKINSIM_TSAN=ON (docs/testing.md says which tests it runs).
if(SKINSIM_TSAN)
  if(SKINSIM_SANITIZE)
    message(FATAL_ERROR "SKINSIM_TSAN and SKINSIM_SANITIZE cannot be combined: build them apart")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
