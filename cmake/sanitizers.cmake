# Opt-in ASan + UBSan: cmake -DSKINSIM_SANITIZE=ON (CI runs the unit tests this way).
if(SKINSIM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
