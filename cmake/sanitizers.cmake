# Native sanitizer lanes: ZOME_SANITIZE="address;undefined" or "thread".
if(ZOME_SANITIZE AND NOT EMSCRIPTEN)
  string(REPLACE ";" "," _zome_san "${ZOME_SANITIZE}")
  add_compile_options(-fsanitize=${_zome_san} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${_zome_san})
endif()
